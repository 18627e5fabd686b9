# Packaging test (cmake -P): install the query component of the build tree
# into a temporary prefix, then
#   1. build and test tests/packaging/consumer with find_package(towdb)
#      through `ctest --build-and-test` ({fmt}'s find-package-test);
#   2. compile consumer.c with the flags of the installed towdb.pc.
# Inputs: BUILD_DIR, SOURCE_DIR, WORK_DIR, GENERATOR, C_COMPILER, LIBDIR, VERSION,
# SANITIZE (the library was built with TOWDB_SANITIZE: the consumers link the
# sanitizer runtimes too, or the instrumented library cannot be loaded).
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
set(sanitize_flags "")
if(SANITIZE)
  set(sanitize_flags "-fsanitize=address,undefined")
endif()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}" --component query)
foreach(f include/towdb/query.h include/towdb/query.hpp ${LIBDIR}/cmake/towdb/towdbConfig.cmake
          ${LIBDIR}/cmake/towdb/towdbConfigVersion.cmake ${LIBDIR}/pkgconfig/towdb.pc)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()

run(${CMAKE_CTEST_COMMAND} --build-and-test "${SOURCE_DIR}" "${WORK_DIR}/consumer"
    --build-generator "${GENERATOR}"
    --build-options "-DCMAKE_PREFIX_PATH=${prefix}" "-DTOWDB_EXPECTED_VERSION=${VERSION}"
                    "-DCMAKE_C_COMPILER=${C_COMPILER}" "-DCMAKE_EXE_LINKER_FLAGS=${sanitize_flags}"
    --test-command ${CMAKE_CTEST_COMMAND} --output-on-failure)
message(STATUS "find_package consumer:\n${run_output}")

find_program(PKG_CONFIG_EXECUTABLE pkg-config)
if(PKG_CONFIG_EXECUTABLE)
  set(ENV{PKG_CONFIG_PATH} "${prefix}/${LIBDIR}/pkgconfig")
  run(${PKG_CONFIG_EXECUTABLE} --cflags --libs towdb)
  string(STRIP "${run_output}" flags)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  run(${PKG_CONFIG_EXECUTABLE} --modversion towdb)
  string(STRIP "${run_output}" pc_version)
  if(NOT pc_version STREQUAL VERSION)
    message(FATAL_ERROR "towdb.pc version ${pc_version}, expected ${VERSION}")
  endif()
  run("${C_COMPILER}" -std=c11 -Wall -Wextra -Werror ${sanitize_flags} "${SOURCE_DIR}/consumer.c" ${flags}
      "-Wl,-rpath,${prefix}/${LIBDIR}" -o "${WORK_DIR}/consumer_pc")
  run("${WORK_DIR}/consumer_pc" "${VERSION}")
  message(STATUS "pkg-config consumer: ${run_output}")
else()
  message(STATUS "pkg-config not found: towdb.pc checked for presence only")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
