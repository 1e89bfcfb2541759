# The scheduling does not change what validate finds: the same scenes
# validated with the reference, POV-Ray and Blender renderers once with
# every job and every case one after the other (--jobs 1 --batch 1
# --schedule count: one job at a time, one Blender process per scene, the
# compare step's cases in turn) and once with the defaults and --jobs 4
# (Blender batches, jobs weighted by their renderer's cpu_share, four
# cases compared at once). results.json and report.html must agree except
# for timings (tests/cluster/compare_runs.py: the cases in plan order too),
# then the parallel run's compare step alone again (--compare-only --jobs 1)
# must agree with it as well.
# -DXVAL=... -DPYTHON=... -DCOMPARE=... -DOUT=... -DSCENES="a.json;b.json;..."
file(REMOVE_RECURSE ${OUT})
foreach(variant serial parallel)
  if(variant STREQUAL "serial")
    set(flags --jobs 1 --batch 1 --schedule count)
  else()
    set(flags --jobs 4)
  endif()
  execute_process(COMMAND ${XVAL} validate -o ${OUT}/${variant} --export-cache ${OUT}/${variant}.cache
                          --renderers reference,povray,blender ${flags} -- ${SCENES}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${variant} run: exit ${rc} (expected 0: every scene passes):\n${out}${err}")
  endif()
endforeach()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${OUT}/serial ${OUT}/parallel
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the serial and the parallel run's results differ (compare_runs.py exit ${rc}):\n${out}${err}")
endif()
file(COPY ${OUT}/parallel/ DESTINATION ${OUT}/recompared)
execute_process(COMMAND ${XVAL} validate --plan ${OUT}/recompared/jobs.json --compare-only --jobs 1
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "--compare-only --jobs 1 of the parallel run: exit ${rc}:\n${out}${err}")
endif()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${OUT}/parallel ${OUT}/recompared
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the parallel run's compare step and a serial one differ (compare_runs.py exit ${rc}):\n${out}${err}")
endif()
