# Steps shared by the CTest tests that build and run tests in a second, instrumented tree
# (unit/io/sanitize_io.cmake and sanitize/sanitize_suite.cmake: ASan + UBSan;
# unit/tsan/tsan_parallel.cmake: ThreadSanitizer).
# Included by those scripts (cmake -P), which get SRC, BIN and DATA from the test command.

# Configures ${tree} from SRC: no UI, no benchmarks, Debug at -O1 -g1, plus the given options.
function(plumb_configure_second_tree tree what)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S ${SRC} -B ${tree} -G Ninja -DPLUMB_BUILD_UI=OFF
            -DPLUMB_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1"
            "-DCMAKE_C_FLAGS_DEBUG=-O1 -g1" -DPLUMB_SHARED_DATA_DIR=${DATA} ${ARGN}
    RESULT_VARIABLE rc OUTPUT_QUIET)
  if(rc)
    message(FATAL_ERROR "configuring the ${what} tree failed (${rc})")
  endif()
endfunction()

# Builds the given targets in ${tree} on two cores.
function(plumb_build_in_second_tree tree what)
  execute_process(COMMAND ninja -C ${tree} -j2 ${ARGN} RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "building ${ARGN} with ${what} failed (${rc})")
  endif()
endfunction()

# Runs the test executable ${name} of ${tree} in its folder with the given gtest arguments.
function(plumb_run_in_second_tree tree name what)
  file(GLOB_RECURSE exe ${tree}/tests/*/${name})
  list(FILTER exe EXCLUDE REGEX "CMakeFiles")
  if(NOT exe)
    message(FATAL_ERROR "${name} was not built")
  endif()
  get_filename_component(dir ${exe} DIRECTORY)
  execute_process(COMMAND ${exe} --gtest_brief=1 ${ARGN} WORKING_DIRECTORY ${dir} RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${name} failed under ${what} (${rc})")
  endif()
  message(STATUS "${name}: clean under ${what}")
endfunction()
