# A renderer defined by a file in validate's plan (validate/validation/plan.h,
# RendererFile): a plan made with --renderer-file records the definition's
# path and SHA-256, and
#   - its jobs and its compare step run from the plan alone (as a Slurm
#     array task does), with no --renderer-file (which is refused there);
#   - a definition changed since the plan was made is refused by a job;
#   - a resumed run with the changed definition redoes that renderer's job
#     only (the definition is part of its input hash).
# Arguments: XVAL, SCENE, STANDIN (tests/cli/standin_renderer.sh), WORK.
foreach(_v XVAL SCENE STANDIN WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "plan_renderer_file.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def ${WORK}/elsewhere)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)
set(_def ${WORK}/def/standin.json)
set(_text "{\"format\": \"xval-renderer/1\",
 \"name\": \"standin\",
 \"input\": \"scene\",
 \"command\": [\"./standin_renderer.sh\", \"pass\", \"{scene}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./standin_renderer.sh\", \"--version\"]}\n")
file(WRITE ${_def} "${_text}")

set(XVAL_RUN_DIR ${WORK}/elsewhere)
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

set(_out ${WORK}/out)
run_xval(0 _o validate ${SCENE} --renderers reference,standin --renderer-file ${_def} -o ${_out} --plan-only)
file(READ ${_out}/jobs.json _plan)
file(SHA256 ${_def} _hash)
expect("${_plan}" "\"renderer_files\": \\[[ \n]*{[ \n]*\"name\": \"standin\",[ \n]*\"path\": \"${_def}\",[ \n]*\"sha256\": \"${_hash}\""
       "the plan records the renderer file")

run_xval(2 _o validate --plan ${_out}/jobs.json --run-job 1 --renderer-file ${_def})
expect("${_o}" "the renderer files come from the plan" "--plan with --renderer-file")
run_xval(0 _o validate --plan ${_out}/jobs.json --run-job 0)
run_xval(0 _o validate --plan ${_out}/jobs.json --run-job 1)
expect("${_o}" "job 1 tiny standin: ok" "the standin job from the plan alone")
run_xval(0 _o validate --plan ${_out}/jobs.json --compare-only)

# The definition changes (same name, another time-out): the plan's jobs
# refuse it; a resumed run redoes only the standin job.
string(REPLACE "]}\n" "],\n \"timeout_s\": 100}\n" _changed "${_text}")
file(WRITE ${_def} "${_changed}")
file(SHA256 ${_def} _new_hash)
run_xval(2 _o validate --plan ${_out}/jobs.json --run-job 1)
expect("${_o}" "renderer_files\\[0\\].path: ${_def}: the renderer file of standin changed since the plan was made \\(SHA-256 ${_new_hash}, the plan's ${_hash}\\)"
       "a job with a changed renderer file")
run_xval(0 _o validate ${SCENE} --renderers reference,standin --renderer-file ${_def} -o ${_out} --plan-only --resume)
expect("${_o}" "^1\n.*2 jobs .*1 to run" "--resume after the renderer file changed")
file(REMOVE ${_def})
run_xval(2 _o validate --plan ${_out}/jobs.json --compare-only)
expect("${_o}" "the renderer file of standin is missing" "a plan whose renderer file is gone")
