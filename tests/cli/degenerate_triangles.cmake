# The model loader's degenerate-triangle rule is said where a render is
# recorded (geometry/degenerate_triangles.h): a model with one triangle
# that repeats a vertex index and one that reverses an earlier one
# (tests/cli/scenes/degenerate_triangles) gives
#   - `xval render`: a note on stderr naming the file and the counts;
#   - `xval validate --run-job` of the reference's job: the same note in
#     the job's record ("notes"), and on stderr.
# Arguments: XVAL, SCENE, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(degenerate_triangles.cmake XVAL SCENE WORK)
file(REMOVE_RECURSE ${WORK})
set(_note "degenerate.off: 2 of 4 triangles dropped in 1 placed meshes")
set(_counts "1 with a repeated vertex index and 1 repeating an earlier triangle's three vertices")

run(0 ${XVAL} render ${SCENE} -o ${WORK}/render.exr -q)
expect_in("${err}" "xval render: note: ")
expect_in("${err}" "${_note}")
expect_in("${err}" "${_counts}")

run(0 ${XVAL} validate ${SCENE} -o ${WORK}/out --renderers reference,povray --plan-only)
file(READ ${WORK}/out/jobs.json _plan)
string(JSON _n LENGTH "${_plan}" jobs)
set(_job -1)
math(EXPR _last "${_n} - 1")
foreach(_k RANGE ${_last})
  string(JSON _r GET "${_plan}" jobs ${_k} renderer)
  if(_r STREQUAL "reference")
    set(_job ${_k})
  endif()
endforeach()
if(_job EQUAL -1)
  message(FATAL_ERROR "jobs.json has no reference job:\n${_plan}")
endif()
run(0 ${XVAL} validate --plan ${WORK}/out/jobs.json --run-job ${_job})
expect_in("${err}" "note: ")
expect_in("${err}" "${_note}")
file(READ ${WORK}/out/degenerate_triangles/reference.job.json _rec)
get_json(_first "${_rec}" notes 0)
expect_in("${_first}" "${_note}")
expect_in("${_first}" "${_counts}")
