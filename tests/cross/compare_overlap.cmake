# A plain validate run compares a case as soon as its jobs are done, while
# the other jobs still render (validate/validation/run_job.h AfterCase):
# Table 2's knot (its POV-Ray job takes several seconds) and three small
# scenes, reference and POV-Ray, --jobs 2; tests/cross/overlap_check.py
# requires some case's difference images to be older than the last job's
# record, and every case's to be no older than its own jobs' records.
# -DRUN_ARGS="--renderers;reference,blender;--batch;4" instead: Blender's
# batch of all four scenes; a case is compared as soon as the worker has
# finished its scene, while the batch renders the next (Renderer::
# render_batch's item_done), so the first cases' compares come before the
# batch's last record.
# -DXVAL=... -DPYTHON=... -DCHECK=overlap_check.py -DOUT=... -DSCENES="a.json;b.json;..."
#   [-DRUN_ARGS=... -DCHECK_ARGS="--batch;blender"]
if(NOT DEFINED RUN_ARGS)
  set(RUN_ARGS --renderers reference,povray)
endif()
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${XVAL} validate -o ${OUT}/run --export-cache ${OUT}/cache
                        ${RUN_ARGS} --jobs 2 -- ${SCENES}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "validate: exit ${rc} (expected 0: every scene passes):\n${out}${err}")
endif()
message("${err}")
execute_process(COMMAND ${PYTHON} ${CHECK} ${OUT}/run ${CHECK_ARGS}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "overlap_check.py exit ${rc}:\n${out}${err}")
endif()
