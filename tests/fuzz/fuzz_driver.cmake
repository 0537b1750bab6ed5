# cmake -P script behind the fuzz CTest tests (see tests/fuzz/CMakeLists.txt).
#   MODE=build: configure + build the clang tree FUZZ_ROOT/tree for MODULES.
#   MODE=run:   run FUZZ_ROOT/tree/fuzz_MODULE on its corpus for a fixed number of inputs (scaled
#               by SECONDS) with libFuzzer's -seed=FUZZ_SEED (0: random, for SECONDS); fail on
#               a crash, printing the report and the crash input replayed alone.
cmake_minimum_required(VERSION 3.25)

if(MODE STREQUAL "build")
  include(ProcessorCount)
  ProcessorCount(jobs)
  if(jobs EQUAL 0)
    set(jobs 2)
  endif()
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S ${PLUMB_SOURCE_DIR}/tests/fuzz/standalone -B ${FUZZ_ROOT}/tree
      -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
      -DCMAKE_CXX_COMPILER=${CLANGXX} -DCMAKE_C_COMPILER=${CLANG}
      -DPLUMB_SOURCE_DIR=${PLUMB_SOURCE_DIR} "-DPLUMB_FUZZ_MODULES=${MODULES}"
    COMMAND_ERROR_IS_FATAL ANY)
  # Keep going past a module that does not compile (-k 0), so one broken reader does not stop
  # the others from being fuzzed; its run test then fails saying it was not built. Binaries
  # are removed first so a stale one is never fuzzed in place of a failed build.
  foreach(module ${MODULES})
    file(REMOVE ${FUZZ_ROOT}/tree/fuzz_${module})
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} --build ${FUZZ_ROOT}/tree -j ${jobs} -- -k 0
                  OUTPUT_FILE ${FUZZ_ROOT}/build.log ERROR_FILE ${FUZZ_ROOT}/build.log
                  RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(WARNING "fuzz: some fuzzers did not build (see ${FUZZ_ROOT}/build.log); "
                    "their fuzz_<module> tests will fail")
  endif()
  return()
endif()

if(NOT MODE STREQUAL "run")
  message(FATAL_ERROR "fuzz_driver.cmake: MODE must be build or run")
endif()

set(binary ${FUZZ_ROOT}/tree/fuzz_${MODULE})
if(NOT EXISTS ${binary})
  set(log "")
  if(EXISTS ${FUZZ_ROOT}/build.log)
    file(STRINGS ${FUZZ_ROOT}/build.log log REGEX "error|FAILED")
  endif()
  message(FATAL_ERROR "fuzz: ${binary} was not built (the fuzz_build test builds it; "
                      "${FUZZ_ROOT}/build.log):\n${log}")
endif()

set(seed_dir ${FUZZ_ROOT}/seeds/${MODULE})
set(corpus_dir ${FUZZ_ROOT}/corpus/${MODULE})
set(crash_dir ${FUZZ_ROOT}/crashes/${MODULE})
file(REMOVE_RECURSE ${seed_dir})
file(MAKE_DIRECTORY ${seed_dir} ${corpus_dir} ${crash_dir})
# Seeds: every file up to 1 MiB (big seeds slow every run) of shared/data/<module>,
# tests/fuzz/seeds/<module> and tests/unit/<module>/data, whichever exist. The model path's
# shared files are the IFC models (its in-process parsers read IFC text).
set(shared_name ${MODULE})
if(MODULE STREQUAL "model")
  set(shared_name ifc)
endif()
set(source_seeds ${SHARED_DATA_DIR}/${shared_name} ${PLUMB_SOURCE_DIR}/tests/fuzz/seeds/${MODULE}
                 ${PLUMB_SOURCE_DIR}/tests/unit/${MODULE}/data)
set(count 0)
foreach(dir ${source_seeds})
  if(NOT IS_DIRECTORY ${dir})
    continue()
  endif()
  file(GLOB seeds ${dir}/*)
  foreach(seed ${seeds})
    if(IS_DIRECTORY ${seed})
      continue()
    endif()
    file(SIZE ${seed} size)
    if(size LESS_EQUAL 1048576)
      file(COPY ${seed} DESTINATION ${seed_dir})
      math(EXPR count "${count} + 1")
    endif()
  endforeach()
endforeach()
if(NOT DEFINED FUZZ_SEED)
  set(FUZZ_SEED 1)
endif()

# The PCD seeds of shared/data are ~1 MB LZF captures: whole, they leave fuzz_pcd 34 inputs/s
# (decompressed and converted under ASan). Cut to 16 KiB they still reach every header and size
# check and PCL's truncation paths, while the small seeds of tests/fuzz/seeds/pcd go through.
# The IFC seeds (113-710 KB) likewise: whole, fuzz_model ran 6 inputs/s (each input goes
# through about ten scans); cut to 16 KiB, 180/s, and their heads still hold the project, units,
# contexts and often the site, while tests/fuzz/seeds/model covers the georeferencing.
set(extra_options)
if(MODULE STREQUAL "pcd" OR MODULE STREQUAL "model")
  list(APPEND extra_options -max_len=16384)
endif()

# How many inputs each fuzzer tries: about what PLUMB_FUZZ_SECONDS (15 s) gave each of them on
# a 2-core CI machine. A fixed count instead of a time limit makes the run the same everywhere:
# same binary, same seed files, same -seed, same inputs, whatever the machine's speed or load.
# The time limit stays as a cap (8x) so a slow machine cannot hang the suite.
set(runs_e57 2000)
set(runs_las 4500)
set(runs_model 3500)
set(runs_pcd 100000)
set(runs_ply 120000)
set(runs_text 140000)
set(runs 20000)
if(DEFINED runs_${MODULE})
  set(runs ${runs_${MODULE}})
endif()
math(EXPR runs "${runs} * ${SECONDS} / 15")
math(EXPR cap "${SECONDS} * 8")
if(FUZZ_SEED EQUAL 0)  # a hunt for new bugs: as many inputs as the time allows
  set(runs -1)
  set(cap ${SECONDS})
endif()
message(STATUS "fuzz_${MODULE}: ${count} seeds, -seed=${FUZZ_SEED}, -runs=${runs} (at most ${cap} s)")

set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0")
set(ENV{UBSAN_OPTIONS} "halt_on_error=1:print_stacktrace=1")
set(log ${FUZZ_ROOT}/fuzz_${MODULE}.log)
execute_process(
  COMMAND ${binary} -runs=${runs} -max_total_time=${cap} -rss_limit_mb=2048 -timeout=10
    -seed=${FUZZ_SEED} -print_final_stats=1 ${extra_options} -artifact_prefix=${crash_dir}/
    ${corpus_dir} ${seed_dir}
  OUTPUT_FILE ${log} ERROR_FILE ${log} RESULT_VARIABLE rc)
file(STRINGS ${log} stats REGEX "^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)")
string(JOIN "\n" stats ${stats})
message(STATUS "fuzz_${MODULE}: exit ${rc}; full log ${log}\n${stats}")
if(NOT rc EQUAL 0)
  # CI shows the end of the output: put the report there, then each crash input replayed alone
  # (does it crash by itself, or only after the inputs before it?) and its first bytes.
  file(STRINGS ${log} report REGEX "ERROR|SUMMARY|^ *#[0-9]+ 0x|==[0-9]+==|runtime error|Test unit written")
  list(SUBLIST report 0 60 report)
  string(JOIN "\n" report ${report})
  message("fuzz_${MODULE} report:\n${report}")
  file(GLOB crashes ${crash_dir}/*)
  foreach(crash ${crashes})
    execute_process(COMMAND ${binary} -runs=1 ${extra_options} ${crash}
                    OUTPUT_VARIABLE out ERROR_VARIABLE out RESULT_VARIABLE replay_rc)
    string(REGEX MATCHALL "[^\n]*(ERROR|SUMMARY|runtime error|#[0-9]+ 0x)[^\n]*" replay "${out}")
    list(SUBLIST replay 0 30 replay)
    string(JOIN "\n" replay ${replay})
    file(READ ${crash} head LIMIT 256 HEX)
    message("replayed alone: ${crash} (exit ${replay_rc})\n${replay}\nfirst bytes (hex): ${head}")
  endforeach()
  message(FATAL_ERROR "fuzz_${MODULE} failed (exit ${rc}); crash inputs: ${crashes}")
endif()
