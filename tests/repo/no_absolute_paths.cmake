# The repository stands alone (issue 19): no source, test, document or build
# file names a build machine's absolute path. Run as
#   cmake -DSOURCE_DIR=<repository> -P tests/repo/no_absolute_paths.cmake
# Fails (and lists file:line) on a path under a build machine's work, home,
# Users or root folder (the pattern below) in any text file of the listed
# folders (test data included: its headers cite their sources); this file is
# exempt.
if(NOT SOURCE_DIR)
  message(FATAL_ERROR "no_absolute_paths: pass -DSOURCE_DIR=<repository root>")
endif()
set(_folders generator query cli schema ships db/sweeps docs scripts bench cmake tests .ci python examples)
set(_patterns "*.cpp" "*.hpp" "*.h" "*.c" "*.cmake" "CMakeLists.txt" "*.md" "*.toml" "*.sql" "*.sh" "*.py" "run"
    "*.csv" "*.txt" "*.json" "*.html")
set(_files "${SOURCE_DIR}/README.md" "${SOURCE_DIR}/CMakeLists.txt")
foreach(folder IN LISTS _folders)
  foreach(pattern IN LISTS _patterns)
    file(GLOB_RECURSE _found "${SOURCE_DIR}/${folder}/${pattern}")
    list(APPEND _files ${_found})
  endforeach()
endforeach()
list(REMOVE_DUPLICATES _files)
set(_bad "")
foreach(f IN LISTS _files)
  if(f MATCHES "no_absolute_paths\\.cmake$")
    continue()
  endif()
  file(STRINGS "${f}" _lines REGEX "(^|[^A-Za-z0-9_.~-])/(work|home|Users|root)/")
  foreach(line IN LISTS _lines)
    file(RELATIVE_PATH _rel "${SOURCE_DIR}" "${f}")
    string(APPEND _bad "  ${_rel}: ${line}\n")
  endforeach()
endforeach()
if(_bad)
  message(FATAL_ERROR "absolute paths of a build machine in the repository (use paths relative to the repository):\n${_bad}")
endif()
list(LENGTH _files _n)
message(STATUS "no_absolute_paths: ${_n} files checked")
