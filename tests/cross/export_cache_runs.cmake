# The export cache (renderers/export_cache.h) across `xval validate` runs:
#  1. cold then warm on one new cache folder: the first run stores every
#     export, the second restores them ("export cache: cached", nothing
#     stored), and both agree apart from timings (tests/cluster/
#     compare_runs.py);
#  2. two runs started together on another new cache folder (one
#     execute_process, two commands: they run at once) both exit 0 and
#     agree with the cold run; the folder then holds whole entries only
#     (each with its manifest, no temporary left).
# -DXVAL=... -DPYTHON=... -DCOMPARE=... -DTOLERANCES=... -DWORK=... -DSCENES=a.json;b.json
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(args validate --renderers reference,povray,blender --tolerances ${TOLERANCES} ${SCENES})

function(agree a b)
  execute_process(COMMAND ${PYTHON} ${COMPARE} ${WORK}/${a} ${WORK}/${b} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${a} and ${b} disagree (compare_runs exit ${rc}):\n${out}${err}")
  endif()
endfunction()

foreach(run cold warm)
  execute_process(COMMAND ${XVAL} ${args} --export-cache ${WORK}/cache -o ${WORK}/${run}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the ${run} run failed (exit ${rc}):\n${out}${err}")
  endif()
  set(${run}_err "${err}")
endforeach()
if(NOT cold_err MATCHES "export cache: stored")
  message(FATAL_ERROR "the cold run stored nothing in the cache:\n${cold_err}")
endif()
if(NOT warm_err MATCHES "export cache: cached" OR warm_err MATCHES "export cache: stored")
  message(FATAL_ERROR "the warm run did not take every export from the cache:\n${warm_err}")
endif()
agree(cold warm)

execute_process(COMMAND ${XVAL} ${args} --export-cache ${WORK}/shared -o ${WORK}/concurrent_a
                COMMAND ${XVAL} ${args} --export-cache ${WORK}/shared -o ${WORK}/concurrent_b
                RESULTS_VARIABLE rcs OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rcs STREQUAL "0;0")
  message(FATAL_ERROR "the concurrent runs exited ${rcs}:\n${out}${err}")
endif()
agree(cold concurrent_a)
agree(cold concurrent_b)
file(GLOB entries LIST_DIRECTORIES true ${WORK}/shared/* ${WORK}/shared/.*)
if(NOT entries)
  message(FATAL_ERROR "${WORK}/shared: the concurrent runs stored nothing")
endif()
foreach(e IN LISTS entries)
  get_filename_component(n ${e} NAME)
  if(n MATCHES "^\\." OR NOT EXISTS ${e}/manifest.json)
    message(FATAL_ERROR "${e}: not a whole entry")
  endif()
endforeach()
