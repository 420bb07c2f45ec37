# Runs one libFuzzer target for CTest (tests/fuzz/CMakeLists.txt, docs/fuzzing.md):
#   cmake -DFUZZER=... -DSOURCE_DIR=... -DSEEDS="glob|glob" -DREGRESSIONS=dir -DDICTIONARY=file -DWORK=dir
#         -DMAX_LEN=bytes -DINPUT_TIMEOUT=s -DMODE=replay|fuzz [-DSECONDS=s] -P RunFuzzer.cmake
# replay: every seed (the SEEDS globs under SOURCE_DIR, read now) and every regression input, once each.
# fuzz:   fuzzes for SECONDS from the seeds, the regression inputs and WORK/corpus; what it finds new goes to
#         WORK/corpus (the build tree, never the sources), a failing input to WORK/artifacts.
# Either fails on a crash, a sanitizer report, a leak, an input slower than INPUT_TIMEOUT, or more than 2 GB of memory.
string(REPLACE "|" ";" SEEDS "${SEEDS}")
set(seeds)
foreach(glob ${SEEDS})
  file(GLOB_RECURSE found ${SOURCE_DIR}/${glob})
  list(APPEND seeds ${found})
endforeach()
if(NOT seeds)
  message(FATAL_ERROR "no seed inputs match ${SEEDS} under ${SOURCE_DIR}")
endif()
file(GLOB regressions ${REGRESSIONS}/*)

set(limits -timeout=${INPUT_TIMEOUT} -rss_limit_mb=2048)
if(MODE STREQUAL "replay")
  execute_process(COMMAND ${FUZZER} ${limits} ${seeds} ${regressions} RESULT_VARIABLE status)
elseif(MODE STREQUAL "fuzz")
  file(MAKE_DIRECTORY ${WORK}/corpus ${WORK}/artifacts)
  string(REPLACE ";" "," seed_list "${seeds}")
  set(corpora ${WORK}/corpus)
  if(regressions)
    list(APPEND corpora ${REGRESSIONS})  # read only: libFuzzer adds new inputs to the first corpus alone
  endif()
  execute_process(COMMAND ${FUZZER} ${limits} -max_total_time=${SECONDS} -max_len=${MAX_LEN} -dict=${DICTIONARY}
                          -detect_leaks=1 -print_final_stats=1 -artifact_prefix=${WORK}/artifacts/
                          -seed_inputs=${seed_list} ${corpora}
                  RESULT_VARIABLE status)
else()
  message(FATAL_ERROR "MODE must be replay or fuzz, not \"${MODE}\"")
endif()
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${FUZZER} failed (${status}). The input is named above (a fuzz run leaves it in "
                      "${WORK}/artifacts); copy it into ${REGRESSIONS}/ to keep it as a regression test "
                      "(docs/fuzzing.md).")
endif()
