# One short libFuzzer run: a fresh scratch corpus (new inputs go there, the
# seed folders are only read), a fixed seed, RUNS inputs. Fails on any
# finding (libFuzzer exits non-zero and writes the input to WORK/crash-*).
foreach(_v FUZZER WORK DICT RUNS SEEDS)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "smoke.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/corpus)
execute_process(
  COMMAND ${FUZZER} -seed=1 -runs=${RUNS} -max_len=8192 -timeout=25 -rss_limit_mb=2048
          -dict=${DICT} -artifact_prefix=${WORK}/ -print_final_stats=1
          ${WORK}/corpus ${SEEDS}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE out)
string(REGEX MATCHALL "(#[0-9]+[^\n]*DONE[^\n]*|stat::[^\n]*)" stats "${out}")
string(REPLACE ";" "\n" stats "${stats}")
message("${stats}")
if(NOT rc EQUAL 0)
  file(GLOB found ${WORK}/crash-* ${WORK}/timeout-* ${WORK}/oom-* ${WORK}/leak-*)
  message(FATAL_ERROR "fuzzer exit status ${rc}; inputs kept: ${found}\n${out}")
endif()
