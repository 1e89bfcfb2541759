# Scene warnings (lint/scene_lint.h, docs/scene-format.md "Warnings") are
# said and recorded, never a verdict:
#   - `xval validate` of a scene with a point light inside its sphere (and
#     a directional light that lights it) prints the warning once on
#     stderr, records it in the case's "warnings" in results.json, shows it
#     in the report beside the case, and the case still passes (exit 0);
#     a stand-in POV-Ray writes the reference render, so the pair passes;
#   - `xval render` and `xval lint` print it too (lint: exit 0); a scene
#     without one (tiny) gets none.
# Arguments: XVAL, SCENE (the light-inside scene), CLEAN (tiny.json), WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(scene_warnings.cmake XVAL SCENE CLEAN WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin)

set(_warning "warning: light_inside_sphere: lights[0]: the point light is inside the closed surface of objects[0]")
run(0 ${XVAL} render ${SCENE} -o ${WORK}/ref.exr --precision double -q)
expect_in("${err}" "xval render: ${_warning}")
run(0 ${XVAL} render ${CLEAN} -o ${WORK}/clean.exr -q)
string(FIND "${err}" "warning" _at)
expect_eq("a warning for ${CLEAN}" "${_at}" "-1")
run(0 ${XVAL} lint ${SCENE} ${CLEAN})
expect_in("${err}" "xval lint: ${_warning}")
expect_in("${err}" "xval lint: 1 warning(s) in 2 scene(s)")

write_povray_stand_in(${WORK}/bin "/bin/cp '${WORK}/ref.exr' \"$out\"")
run(0 ${CMAKE_COMMAND} -E env "PATH=${WORK}/bin:/usr/bin:/bin"
    ${XVAL} validate ${SCENE} -o ${WORK}/out --jobs 1 --timeout 60 --renderers reference,povray)
string(REGEX MATCHALL "xval validate: warning: [^\n]*" _lines "${err}")
list(LENGTH _lines _n)
expect_eq("warning lines on stderr" "${_n}" "1")
expect_in("${_lines}" "${_warning}")
expect_in("${_lines}" "[light_inside_closed_mesh]")

file(READ ${WORK}/out/results.json _results)
get_json(_case "${_results}" cases 0)
get_json(_pass "${_case}" pass)
expect_eq("the case's pass" "${_pass}" "ON")
string(JSON _nw LENGTH "${_case}" warnings)
expect_eq("the case's warnings" "${_nw}" "1")
get_json(_code "${_case}" warnings 0 code)
expect_eq("the warning's code" "${_code}" "light_inside_closed_mesh")
get_json(_subject "${_case}" warnings 0 subject)
expect_eq("the warning's subject" "${_subject}" "lights[0]")

file(READ ${WORK}/out/report.html _report)
expect_in("${_report}" "<p class=\"warn\">warning: lights[0]: the point light is inside the closed surface of objects[0]")
