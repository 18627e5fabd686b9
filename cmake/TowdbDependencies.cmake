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

# towdb serve: cpp-httplib (Debian builds it as a library with a .pc file) and
# the Chart.js the page draws with, served locally (no network at run time).
if(PkgConfig_FOUND)
  pkg_check_modules(CPPHTTPLIB QUIET IMPORTED_TARGET cpp-httplib)
endif()
towdb_require(CPPHTTPLIB_FOUND "cpp-httplib" "libcpp-httplib-dev")
set(TOWDB_CHART_JS "/usr/share/javascript/chart.js/chart.min.js" CACHE FILEPATH
    "Chart.js served by towdb serve (Debian libjs-chart.js)")
if(NOT EXISTS "${TOWDB_CHART_JS}")
  list(APPEND _towdb_missing "Chart.js at ${TOWDB_CHART_JS} (Debian package libjs-chart.js)")
endif()

# The Python module (TOWDB_PYTHON). Not under TOWDB_SANITIZE: a module built
# with ASan can only be loaded into an interpreter started with the ASan
# runtime preloaded (LD_PRELOAD), which Debian's python3 is not; the C API it
# wraps is tested under the sanitizers by tests/query.
set(TOWDB_PYTHON_MODULE OFF)
if(TOWDB_PYTHON AND TOWDB_SANITIZE)
  message(STATUS "towdb: TOWDB_SANITIZE=ON: the Python module and its tests are not built")
elseif(TOWDB_PYTHON)
  # Debian's interpreter, the one that python3-pytest, python3-pandas and
  # python3-selenium serve (a pyenv or venv python3 first on PATH would not see
  # them); -DPython3_EXECUTABLE=... chooses another.
  if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python interpreter of the towdb module and its tests")
  endif()
  find_package(Python3 QUIET COMPONENTS Interpreter Development.Module)
  towdb_require(Python3_FOUND "Python 3 headers (TOWDB_PYTHON)" "python3-dev")
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 2.6 QUIET CONFIG)
  towdb_require(pybind11_FOUND "pybind11 (TOWDB_PYTHON)" "pybind11-dev")
  set(TOWDB_PYTHON_MODULE ON)
endif()

# towdb_require_python_module(<module> <debian package>): the test interpreter
# imports <module>, or configuring fails naming the package.
macro(towdb_require_python_module module debian_package)
  execute_process(COMMAND "${Python3_EXECUTABLE}" -c "import ${module}"
                  RESULT_VARIABLE _towdb_py_rc OUTPUT_QUIET ERROR_QUIET)
  if(NOT _towdb_py_rc EQUAL 0)
    list(APPEND _towdb_missing "Python module ${module} for ${Python3_EXECUTABLE} (Debian package ${debian_package})")
  endif()
endmacro()

if(TOWDB_BUILD_TESTS)
  if(TOWDB_PYTHON_MODULE)
    towdb_require_python_module(pytest python3-pytest)
    towdb_require_python_module(pandas python3-pandas)
  endif()
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
