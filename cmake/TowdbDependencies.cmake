# Finds every dependency and says clearly what is missing and how to get it.
# All of them come from Debian packages: scripts/install-deps.sh installs them.

set(_towdb_missing "")
macro(towdb_require found package_name debian_package)
  if(NOT ${found})
    list(APPEND _towdb_missing "${package_name} (Debian package ${debian_package})")
  endif()
endmacro()

find_package(Eigen3 3.3 QUIET NO_MODULE)
towdb_require(Eigen3_FOUND "Eigen3" "libeigen3-dev")

find_package(SQLite3 QUIET)
towdb_require(SQLite3_FOUND "SQLite3" "libsqlite3-dev")

find_package(OpenSSL QUIET COMPONENTS Crypto)
towdb_require(OpenSSL_FOUND "OpenSSL libcrypto" "libssl-dev")

find_package(OpenMP QUIET COMPONENTS CXX)
towdb_require(OpenMP_CXX_FOUND "OpenMP" "a compiler with OpenMP (g++)")

find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(FFTW3 QUIET IMPORTED_TARGET fftw3)
endif()
towdb_require(FFTW3_FOUND "FFTW3" "libfftw3-dev and pkg-config")

find_package(CLI11 QUIET CONFIG)
towdb_require(CLI11_FOUND "CLI11" "libcli11-dev")

find_package(tomlplusplus QUIET CONFIG)
towdb_require(tomlplusplus_FOUND "toml++" "libtomlplusplus-dev")

find_package(nlohmann_json 3.9 QUIET CONFIG)
towdb_require(nlohmann_json_FOUND "nlohmann_json" "nlohmann-json3-dev")

find_package(Threads REQUIRED)

if(TOWDB_BUILD_TESTS)
  find_package(GTest QUIET CONFIG)
  towdb_require(GTest_FOUND "GoogleTest" "libgtest-dev libgmock-dev")
endif()
if(TOWDB_BUILD_BENCH)
  find_package(benchmark QUIET CONFIG)
  towdb_require(benchmark_FOUND "Google Benchmark" "libbenchmark-dev")
endif()
if(TOWDB_MPI)
  find_package(MPI QUIET COMPONENTS CXX)
  towdb_require(MPI_CXX_FOUND "MPI" "libopenmpi-dev openmpi-bin")
endif()

if(_towdb_missing)
  list(JOIN _towdb_missing "\n  " _towdb_missing_text)
  message(FATAL_ERROR "towdb: missing dependencies:\n  ${_towdb_missing_text}\n"
                      "Run scripts/install-deps.sh (as root) to install them.")
endif()
