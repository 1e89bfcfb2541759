# A plain validate run compares a case as soon as its jobs are done, while
# the other jobs still render (validate/validation/run_job.h AfterCase):
# Table 2's knot (its POV-Ray job takes several seconds) and three small
# scenes, reference and POV-Ray, --jobs 2; tests/cross/overlap_check.py
# requires some case's difference images to be older than the last job's
# record, and every case's to be no older than its own jobs' records.
# -DXVAL=... -DPYTHON=... -DCHECK=overlap_check.py -DOUT=... -DSCENES="a.json;b.json;..."
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${XVAL} validate -o ${OUT}/run --export-cache ${OUT}/cache
                        --renderers reference,povray --jobs 2 -- ${SCENES}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "validate: exit ${rc} (expected 0: every scene passes):\n${out}${err}")
endif()
message("${err}")
execute_process(COMMAND ${PYTHON} ${CHECK} ${OUT}/run
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "overlap_check.py exit ${rc}:\n${out}${err}")
endif()
