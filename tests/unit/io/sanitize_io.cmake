# Run by the CTest test "io_sanitize" (label sanitize): configures a second build tree with
# AddressSanitizer + UBSan, builds only the I/O test executables (test_io_ply, test_io,
# test_io_hostile - the hostile inputs and the fuzz crash regressions, whose undefined
# behaviour only UBSan reports - and test_e57 / test_las when those targets exist) and runs
# them. Inputs: SRC, BIN, DATA.
set(tree ${BIN}/sanitize-io)
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SRC} -B ${tree} -G Ninja -DPLUMB_SANITIZE=ON -DPLUMB_BUILD_UI=OFF
          -DPLUMB_BUILD_BENCH=OFF -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1"
          "-DCMAKE_C_FLAGS_DEBUG=-O1 -g1" -DPLUMB_SHARED_DATA_DIR=${DATA}
  RESULT_VARIABLE rc OUTPUT_QUIET)
if(rc)
  message(FATAL_ERROR "configuring the sanitizer tree failed (${rc})")
endif()
execute_process(COMMAND ninja -C ${tree} -t targets all OUTPUT_VARIABLE targets)
set(tests test_io_ply test_io test_io_hostile)
foreach(t test_e57 test_las)
  if(targets MATCHES "(^|\n)${t}:")
    list(APPEND tests ${t})
  endif()
endforeach()
execute_process(COMMAND ninja -C ${tree} -j2 ${tests} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building ${tests} with sanitizers failed (${rc})")
endif()
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0")
set(ENV{LSAN_OPTIONS} "suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan_suppressions.txt")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
foreach(t ${tests})
  file(GLOB_RECURSE exe ${tree}/tests/*/${t})
  list(FILTER exe EXCLUDE REGEX "CMakeFiles")
  if(NOT exe)
    message(FATAL_ERROR "${t} was not built")
  endif()
  get_filename_component(dir ${exe} DIRECTORY)
  execute_process(COMMAND ${exe} --gtest_brief=1 WORKING_DIRECTORY ${dir} RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "${t} failed under AddressSanitizer/UBSan (${rc})")
  endif()
  message(STATUS "${t}: clean under AddressSanitizer/UBSan")
endforeach()
