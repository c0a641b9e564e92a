#!/usr/bin/env bash
# Installs the build and test dependencies from Debian packages. Idempotent; needs root
# (or sudo) only when something is missing.
set -euo pipefail
packages=(build-essential cmake pkg-config git clang-format clang libclang-rt-14-dev
          libfftw3-dev libeigen3-dev libcli11-dev nlohmann-json3-dev libfmt-dev
          libtomlplusplus-dev libgtest-dev libgmock-dev libbenchmark-dev
          python3-dev pybind11-dev python3-numpy python3-matplotlib python3-pytest
          libopenmpi-dev openmpi-bin libhdf5-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq "${missing[@]}"
fi
