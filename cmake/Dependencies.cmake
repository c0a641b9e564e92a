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
if(ROLLCONTACT_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(ROLLCONTACT_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
