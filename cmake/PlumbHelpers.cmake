# plumb_core_module(NAME [DEPENDS targets...] [PRIVATE_DEPENDS targets...])
# Builds the *.cpp of the calling folder into the static library plumb_<NAME> and adds it to
# the plumb_core umbrella target. Headers are included relative to core/, e.g.
# #include "model/point_cloud.hpp" or #include "io/e57/e57_reader.hpp".
function(plumb_core_module name)
  cmake_parse_arguments(ARG "" "" "DEPENDS;PRIVATE_DEPENDS" ${ARGN})
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.cpp)
  add_library(plumb_${name} STATIC ${sources})
  target_include_directories(plumb_${name} PUBLIC ${PROJECT_SOURCE_DIR}/core)
  target_link_libraries(plumb_${name} PUBLIC ${ARG_DEPENDS} PRIVATE ${ARG_PRIVATE_DEPENDS})
  target_compile_options(plumb_${name} PRIVATE -Wall -Wextra)
  set_target_properties(plumb_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  set_property(GLOBAL APPEND PROPERTY PLUMB_CORE_MODULES plumb_${name})
endfunction()

# plumb_sanitized_timeout(VAR): in a sanitizer tree (tests/sanitize, tsan) the same tests run
# 2-5 times slower, more on a loaded machine: their time limits are 4 times the normal ones.
function(plumb_sanitized_timeout var)
  if(PLUMB_SANITIZE OR PLUMB_TSAN)
    math(EXPR scaled "${${var}} * 4")
    set(${var} ${scaled} PARENT_SCOPE)
  endif()
endfunction()

# plumb_add_test(NAME SOURCES files... LIBS targets... [LABELS labels...] [TIMEOUT s] [RUNS_CLI])
# A GoogleTest executable registered with CTest, one CTest test per gtest case.
function(plumb_add_test name)
  cmake_parse_arguments(ARG "RUNS_CLI" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  if(NOT ARG_LABELS)
    set(ARG_LABELS unit)
  endif()
  plumb_sanitized_timeout(ARG_TIMEOUT)
  add_executable(${name} ${ARG_SOURCES})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest plumb_gtest_main plumb_test_support)
  # Test code at -O1 in Release: a quarter less compile time than -O2 (measured on the CLI,
  # E57 and params tests); what the tests exercise is the core, built at -O2.
  target_compile_options(${name} PRIVATE -Wall -Wextra $<$<CONFIG:Release>:-O1>)
  if(ARG_RUNS_CLI)
    # End-to-end tests of the real executable (tests/support/cli_runner.hpp).
    target_compile_definitions(${name} PRIVATE PLUMB_CLI_PATH="$<TARGET_FILE:plumb-cli>")
    add_dependencies(${name} plumb-cli)
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60
    PROPERTIES LABELS "${ARG_LABELS}" TIMEOUT ${ARG_TIMEOUT}
    WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
endfunction()

# plumb_add_second_tree_test(NAME SCRIPT LABEL TIMEOUT)
# A CTest test that runs SCRIPT (cmake -P) to build and run tests in a second, instrumented
# tree (tests/second_tree.cmake), with the source, build and data folders it needs.
function(plumb_add_second_tree_test name script label timeout)
  add_test(NAME ${name}
           COMMAND ${CMAKE_COMMAND} -DSRC=${PROJECT_SOURCE_DIR} -DBIN=${CMAKE_BINARY_DIR}
                   -DDATA=${PLUMB_SHARED_DATA_DIR} -P ${script})
  set_tests_properties(${name} PROPERTIES LABELS ${label} TIMEOUT ${timeout})
endfunction()
