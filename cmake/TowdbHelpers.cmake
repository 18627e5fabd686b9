# Per-target compiler settings and the one test-registration helper.

# towdb_target_options(<target>): warnings, and the one code-generation flag
# the results depend on, on the target; never global flags.
function(towdb_target_options target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE
      $<$<COMPILE_LANGUAGE:CXX>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion
                                -Wnon-virtual-dtor -Wold-style-cast -Wunused>
      $<$<COMPILE_LANGUAGE:C>:-Wall -Wextra -Wpedantic>
      # No fused multiply-add contraction, even when CMAKE_CXX_FLAGS enable FMA
      # (-march=native): results stay bit-identical to the bundled database,
      # and the surge integrator's vector lanes to its scalar path.
      -ffp-contract=off)
    if(TOWDB_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
      if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
        # GCC 12 at -O3 reports -Wrestrict inside std::string concatenation that
        # libstdc++ inlines (GCC bug 105329, a false positive): kept as a warning.
        target_compile_options(${target} PRIVATE -Wno-error=restrict)
      endif()
    endif()
  endif()
  if(TOWDB_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer)
    target_link_options(${target} PRIVATE -fsanitize=address,undefined)
  endif()
endfunction()

# towdb_add_module(<name> [DEPENDS <module>...]): one physical model folder under
# generator/<name>/ becomes the static library towdb_<name>, alias towdb::<name>.
# Every .cpp in the folder is a source; the folder's parent (generator/) is the
# include root, so headers are included as "towline/catenary.hpp".
function(towdb_add_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS;LIBS" ${ARGN})
  file(GLOB _sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  add_library(towdb_${name} STATIC ${_sources})
  add_library(towdb::${name} ALIAS towdb_${name})
  target_include_directories(towdb_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/generator>)
  foreach(dep IN LISTS ARG_DEPENDS)
    target_link_libraries(towdb_${name} PUBLIC towdb::${dep})
  endforeach()
  if(ARG_LIBS)
    target_link_libraries(towdb_${name} PUBLIC ${ARG_LIBS})
  endif()
  towdb_target_options(towdb_${name})
  set_property(GLOBAL APPEND PROPERTY TOWDB_MODULES towdb_${name})
endfunction()

# towdb_add_test(<name> SOURCES <files...> LIBS <targets...> [LABELS <labels...>]
#                [TIMEOUT <s>]): one GoogleTest executable, registered with ctest.
# Tests run from the project root so data paths (ships/, tests/data/) resolve.
function(towdb_add_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE towdb_test_support ${ARG_LIBS} GTest::gtest GTest::gmock GTest::gtest_main)
  towdb_target_options(${name})
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  add_test(NAME ${name} COMMAND ${name} --gtest_brief=1 WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  set_tests_properties(${name} PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT}
    ENVIRONMENT "TOWDB_SOURCE_DIR=${PROJECT_SOURCE_DIR};TOWDB_BINARY_DIR=${PROJECT_BINARY_DIR};TOWDB_EXE=$<TARGET_FILE:towdb>")
endfunction()
