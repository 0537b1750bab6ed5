# Run by the CTest test sanitize_suite (tests/sanitize/CMakeLists.txt). Inputs: SRC, BIN, DATA.
# Fails on a configure or build error, and when any test of the unit and integration labels
# fails in the sanitizer tree: an ASan report (overflow, use after free, leak) or a UBSan
# report (halt_on_error) makes that test's process fail.
include(${CMAKE_CURRENT_LIST_DIR}/../second_tree.cmake)
set(tree ${BIN}/sanitize)
set(what "AddressSanitizer/UBSan")
plumb_configure_second_tree(${tree} "sanitizer" -DPLUMB_SANITIZE=ON)
string(TIMESTAMP t0 "%s")
plumb_build_in_second_tree(${tree} ${what})
string(TIMESTAMP t1 "%s")
math(EXPR build_s "${t1} - ${t0}")
message(STATUS "sanitizer tree built in ${build_s} s")
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0:detect_stack_use_after_return=0")
set(ENV{LSAN_OPTIONS} "suppressions=${CMAKE_CURRENT_LIST_DIR}/../unit/io/lsan_suppressions.txt")
set(ENV{UBSAN_OPTIONS} "print_stacktrace=1:halt_on_error=1:suppressions=${CMAKE_CURRENT_LIST_DIR}/ubsan_suppressions.txt")
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir ${tree} -L "unit|integration" -j2
                        --output-on-failure --timeout 1500
                RESULT_VARIABLE rc)
string(TIMESTAMP t2 "%s")
math(EXPR run_s "${t2} - ${t1}")
message(STATUS "unit and integration tests ran under ${what} in ${run_s} s")
if(rc)
  message(FATAL_ERROR "tests failed under ${what} (ctest ${rc}): see the reports above")
endif()
