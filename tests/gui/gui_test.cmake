# plumb_add_gui_test(<name> <source> <timeout_s>): a QTest executable test_<name> on plumb_ui,
# registered as the CTest `<name>` with LABELS gui (needs a display: CI runs under xvfb-run).
# In the sanitizer tree (tests/sanitize) only the lifetime tests are built: the GUI tests that
# remove layers and open projects while tasks run, where a dangling pointer would show.
set(PLUMB_SANITIZED_GUI_TESTS gui_registration_dock gui_registration_runner)
function(plumb_add_gui_test name source timeout)
  if(PLUMB_SANITIZE AND NOT name IN_LIST PLUMB_SANITIZED_GUI_TESTS)
    return()
  endif()
  set(CMAKE_AUTOMOC ON)
  add_executable(test_${name} ${source})
  target_link_libraries(test_${name} PRIVATE plumb_ui Qt6::Test plumb_test_support)
  target_compile_options(test_${name} PRIVATE -Wall -Wextra)
  vtk_module_autoinit(TARGETS test_${name} MODULES ${VTK_LIBRARIES})
  add_test(NAME ${name} COMMAND test_${name})
  plumb_sanitized_timeout(timeout)
  set_tests_properties(${name} PROPERTIES LABELS gui TIMEOUT ${timeout})
endfunction()
