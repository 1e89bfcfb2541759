# A case's verdict is decided once (validate/results/case_verdict.h) and
# every view of it agrees (issue #30, point 1):
#   1. a case where nothing was compared (the scene's `renderers` field,
#      ["reference", "gl", "blender-import"], leaves out every renderer of
#      the run but the reference) is NOT COMPARED, never a pass: exit 1,
#      the console's summary and next steps, results.json (verdict
#      not_compared, pass false), JUnit (a failing testcase, not tests="0")
#      and the report all say so;
#   2. `golden` (the reference renderer's stored images) stands in for
#      `reference` in a scene's `renderers` field: `--renderers
#      golden,reference` on that scene compares the pair reference-golden,
#      and crosscheck --renderer golden takes the scene.
# Arguments: XVAL, SCENE (a small scene file without `renderers`), XSD, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(case_verdict.cmake XVAL SCENE XSD WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/set/scenes)

# The scene, limited as in the issue's set.
file(READ ${SCENE} _text)
string(REGEX REPLACE "\"name\": \"[a-z_]+\"" "\"name\": \"limited\", \"renderers\": [\"reference\", \"gl\", \"blender-import\"]"
       _limited "${_text}")
if(_limited STREQUAL _text)
  message(FATAL_ERROR "case_verdict.cmake: could not limit ${SCENE}'s renderers")
endif()
set(_scene ${WORK}/set/scenes/limited.json)
file(WRITE ${_scene} "${_limited}")

# 1. Nothing compared: povray is left out, the reference alone renders.
run(1 ${XVAL} validate ${_scene} --renderers reference,povray -o ${WORK}/none --junit ${WORK}/none.xml)
expect_in("${err}" "[compared 1/1] limited")
expect_in("${err}" "NOT COMPARED")
expect_in("${err}" "xval validate: 1 scene, NOT COMPARED: 1 not compared; wrote")
expect_in("${err}" "NOT COMPARED limited (nothing to compare)\n  povray left out: the scene is meant for reference, gl and blender-import only")
file(READ ${WORK}/none/results.json _r)
get_json(_v "${_r}" cases 0 verdict)
expect_eq("results.json verdict" "${_v}" "not_compared")
get_json(_pass "${_r}" cases 0 pass)
expect_eq("results.json pass" "${_pass}" "OFF")
expect_valid_junit(${WORK}/none.xml ${XSD})
file(READ ${WORK}/none.xml _junit)
expect_in("${_junit}" "tests=\"1\" failures=\"1\" errors=\"0\" skipped=\"0\"")
expect_in("${_junit}" "<testcase classname=\"limited\" name=\"case\"")
expect_in("${_junit}" "<failure message=\"nothing compared (no image pair, no geometry check): nothing to compare; povray left out: the scene is meant for reference, gl and blender-import only (its `renderers` field)\" type=\"not_compared\"/>")
file(READ ${WORK}/none/report.html _html)
expect_in("${_html}" "<span class=\"pass\">0 pass</span>")
expect_in("${_html}" "<span class=\"nexp\">1 not compared</span>")
expect_in("${_html}" "nexp\">NOT COMPARED</span>")

# 2. golden in place of reference: the scene names reference, its stored
#    images stand in for it.
run(0 ${XVAL} golden update ${WORK}/set/scenes)
run(0 ${XVAL} validate ${WORK}/set/scenes --renderers golden,reference -o ${WORK}/golden --junit ${WORK}/golden.xml)
expect_in("${err}" "xval validate: 1 scene, all pass; wrote")
file(READ ${WORK}/golden/results.json _r)
get_json(_pair "${_r}" cases 0 pairs 0 pair)
expect_eq("the pair of golden and the reference" "${_pair}" "reference-golden")
get_json(_v "${_r}" cases 0 verdict)
expect_eq("results.json verdict" "${_v}" "pass")
string(JSON _lo ERROR_VARIABLE _none GET "${_r}" cases 0 left_out)
if(NOT _none)
  message(FATAL_ERROR "golden was left out of a scene meant for the reference: ${_lo}")
endif()
file(READ ${WORK}/golden.xml _junit)
expect_in("${_junit}" "tests=\"1\" failures=\"0\" errors=\"0\" skipped=\"0\"")
run(0 ${XVAL} crosscheck ${_scene} --renderer golden -o ${WORK}/cross)
