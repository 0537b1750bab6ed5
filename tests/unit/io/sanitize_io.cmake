# Run by the CTest test "io_sanitize" (label sanitize): configures a second build tree with
# AddressSanitizer + UBSan, builds only the I/O test executables (test_io_ply, test_io,
# test_io_hostile - the hostile inputs and the fuzz crash regressions, whose undefined
# behaviour only UBSan reports - and test_e57 / test_las when those targets exist) and runs
# them. Inputs: SRC, BIN, DATA.
include(${CMAKE_CURRENT_LIST_DIR}/../../second_tree.cmake)
set(tree ${BIN}/sanitize-io)
set(what "AddressSanitizer/UBSan")
# -O0: a fifth less build time than -O1 (measured: 438 s against 547 s of CPU), and these
# tests run in seconds either way.
plumb_configure_second_tree(${tree} "sanitizer" -DPLUMB_SANITIZE=ON "-DCMAKE_CXX_FLAGS_DEBUG=-O0 -g1"
                            "-DCMAKE_C_FLAGS_DEBUG=-O0 -g1")
execute_process(COMMAND ninja -C ${tree} -t targets all OUTPUT_VARIABLE targets)
set(tests test_io_ply test_io test_io_hostile)
foreach(t test_e57 test_las)
  if(targets MATCHES "(^|\n)${t}:")
    list(APPEND tests ${t})
  endif()
endforeach()
plumb_build_in_second_tree(${tree} "sanitizers" ${tests})
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0")
set(ENV{LSAN_OPTIONS} "suppressions=${CMAKE_CURRENT_LIST_DIR}/lsan_suppressions.txt")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1")
foreach(t ${tests})
  plumb_run_in_second_tree(${tree} ${t} ${what})
endforeach()
