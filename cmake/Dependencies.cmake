# All dependencies come from Debian packages (see .ci/run for the apt-get list).
find_package(PkgConfig REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 REQUIRED)
# Debian's libtomlplusplus-dev ships a CMake config exporting tomlplusplus::tomlplusplus (compiled
# library mode: TOML_HEADER_ONLY=0, links libtomlplusplus.so).
find_package(tomlplusplus 3.3 REQUIRED)
if(ROLLCONTACT_WITH_FFTW)
  pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
  # Single precision, for the preconditioners (same Debian package, libfftw3-dev).
  pkg_check_modules(FFTW3F REQUIRED IMPORTED_TARGET fftw3f)
endif()
# HDF5 (libhdf5-dev, the C API) for creep-force lookup tables.
pkg_check_modules(HDF5 REQUIRED IMPORTED_TARGET hdf5)
if(ROLLCONTACT_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(ROLLCONTACT_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# The Python package: Debian's interpreter (another python3 may come first on PATH) with
# pybind11-dev. Not in sanitizer or fuzzing builds (the interpreter is not instrumented).
set(ROLLCONTACT_BUILD_PYTHON OFF)
if(ROLLCONTACT_PYTHON AND NOT ROLLCONTACT_SANITIZE AND NOT ROLLCONTACT_SANITIZE_THREAD
   AND NOT ROLLCONTACT_FUZZ)
  if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(Python COMPONENTS Interpreter Development.Module)
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 CONFIG)
  if(Python_FOUND AND pybind11_FOUND)
    set(ROLLCONTACT_BUILD_PYTHON ON)
  else()
    message(WARNING "Python package not built: needs /usr/bin/python3 with python3-dev and pybind11-dev (scripts/install-deps.sh)")
  endif()
endif()
