# validate's own files refuse a field given twice, as scene files do
# (scene/json_reader.h), naming the file and the field: the plan
# (jobs.json), a job record and the tolerance file.
# Arguments: XVAL, SCENE (a scene file), TOLERANCES (a valid tolerance
# file), WORK (scratch folder).
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(duplicate_keys.cmake XVAL SCENE TOLERANCES WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

run(0 ${XVAL} validate ${SCENE} -o ${WORK}/out --plan-only --tolerances ${TOLERANCES})

# The plan, with "format" twice.
file(READ ${WORK}/out/jobs.json _plan)
string(REPLACE "\"format\":" "\"format\": \"xval-validate-plan/1\",\n  \"format\":" _dup "${_plan}")
file(MAKE_DIRECTORY ${WORK}/dup_plan)
file(WRITE ${WORK}/dup_plan/jobs.json "${_dup}")
run(2 ${XVAL} validate --plan ${WORK}/dup_plan/jobs.json --compare-only)
expect_in("${err}" "dup_plan/jobs.json: not valid JSON in field format: duplicate field \"format\"")

# A job of the plan with "renderer" twice, and the plan's budget with
# "max_triangles" twice: the field path names the job and the field.
string(REPLACE "\"renderer\": \"reference\"" "\"renderer\": \"reference\",\n      \"renderer\": \"reference\"" _dup "${_plan}")
file(MAKE_DIRECTORY ${WORK}/dup_job)
file(WRITE ${WORK}/dup_job/jobs.json "${_dup}")
run(2 ${XVAL} validate --plan ${WORK}/dup_job/jobs.json --compare-only)
expect_in("${err}" "dup_job/jobs.json: not valid JSON in field jobs[0].renderer: duplicate field \"renderer\"")
string(REPLACE "\"max_triangles\":" "\"max_triangles\": 5,\n    \"max_triangles\":" _dup "${_plan}")
file(MAKE_DIRECTORY ${WORK}/dup_budget)
file(WRITE ${WORK}/dup_budget/jobs.json "${_dup}")
run(2 ${XVAL} validate --plan ${WORK}/dup_budget/jobs.json --run-job 0)
expect_in("${err}" "dup_budget/jobs.json: not valid JSON in field budget.max_triangles: duplicate field \"max_triangles\"")

# The tolerance file, with "fraction" twice.
file(WRITE ${WORK}/tolerances.json
  "{\"default\": {\"max_abs_16bit\": 2, \"fraction\": 0.5, \"fraction\": 0.999}}\n")
run(2 ${XVAL} validate ${SCENE} -o ${WORK}/out2 --plan-only --tolerances ${WORK}/tolerances.json)
expect_in("${err}" "tolerances.json: not valid JSON in field default.fraction: duplicate field \"fraction\"")

# A job record with "error" twice: the job counts as not done, and the
# reason names the field.
get_filename_component(_name ${SCENE} NAME_WE)
file(WRITE ${WORK}/out/${_name}/reference.job.json
  "{\"format\": \"xval-validate-job/1\", \"scene\": \"${_name}\", \"renderer\": \"reference\",
    \"input_hash\": \"0\", \"seconds\": 1, \"error\": \"x\", \"error\": \"\"}\n")
run(2 ${XVAL} validate --plan ${WORK}/out/jobs.json --compare-only)
file(READ ${WORK}/out/results.json _results)
expect_in("${_results}" "reference.job.json: not valid JSON in field error: duplicate field")
