# Validating a subset of scenes into a folder that holds an earlier run
# updates those cases and keeps the others (validate/validation/plan_update.h),
# with a stand-in POV-Ray that writes the reference render of its case:
#   - a, b, c validated; then a alone: results.json and the report still
#     have a, b, c; a was rendered again, b and c were not;
#   - c's scene file removed, b's changed: a alone keeps neither, each said
#     on stderr with the reason;
#   - other renderers than the folder's: refused, naming both.
# Arguments: XVAL, SCENE (a small scene named "tiny"), WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(subset_update.cmake XVAL SCENE WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin ${WORK}/scenes)
write_renamed_scenes(a b c)
# The stand-in finds its case by the component after out/ in its work folder.
write_povray_stand_in(${WORK}/bin
  "s=$(/bin/echo \"$PWD\" | /bin/sed -n 's|.*/out/\\([^/]*\\)/.*|\\1|p')\n/bin/cp \"${WORK}/ref_$s.exr\" \"$out\"")

function(validate expect_rc)
  validate_with_stand_ins(${expect_rc} ${WORK}/bin ${ARGN} -o ${WORK}/out --jobs 2 --timeout 60)
  set(err "${err}" PARENT_SCOPE)
endfunction()
function(cases var)
  file(READ ${WORK}/out/results.json _r)
  string(JSON _n LENGTH "${_r}" cases)
  set(_names "")
  math(EXPR _last "${_n} - 1")
  foreach(_i RANGE ${_last})
    string(JSON _name GET "${_r}" cases ${_i} scene)
    list(APPEND _names ${_name})
  endforeach()
  set(${var} "${_names}" PARENT_SCOPE)
endfunction()
set(_r --renderers reference,povray)

# 1. a, b, c; then a alone: all three kept in results.json and the report.
validate(0 ${WORK}/scenes ${_r})
cases(_c)
expect_eq("cases after the full run" "${_c}" "a;b;c")
file(TIMESTAMP ${WORK}/out/b/reference.exr _b_before "%s")
file(TIMESTAMP ${WORK}/out/a/reference.exr _a_before "%s")
execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 1.1)
validate(0 ${WORK}/scenes/a.json ${_r})
expect_in("${err}" "keeping 2 earlier cases")
cases(_c)
expect_eq("cases after validating a alone" "${_c}" "a;b;c")
file(TIMESTAMP ${WORK}/out/b/reference.exr _b_after "%s")
file(TIMESTAMP ${WORK}/out/a/reference.exr _a_after "%s")
expect_eq("b's render (kept, not rendered again)" "${_b_after}" "${_b_before}")
if(_a_after STREQUAL _a_before)
  message(FATAL_ERROR "a's render was not made again")
endif()
file(READ ${WORK}/out/report.html _html)
foreach(_s a b c)
  expect_in("${_html}" "id=\"${_s}\"")
endforeach()
expect_in("${err}" "3 scenes, all pass")

# 2. c's file gone, b's changed: neither kept, each with its reason.
file(REMOVE ${WORK}/scenes/c.json)
file(APPEND ${WORK}/scenes/b.json "\n")
validate(0 ${WORK}/scenes/a.json ${_r})
expect_in("${err}" "c.json: dropped: the scene file no longer exists")
expect_in("${err}" "b.json: dropped: its renders are not current")
cases(_c)
expect_eq("cases after b changed and c went" "${_c}" "a")

# 3. The folder's cases were made with reference and povray: another set
#    of renderers is refused (a and b's folder holds only a now, so add b).
validate(0 ${WORK}/scenes/b.json ${_r})
validate(2 ${WORK}/scenes/a.json --renderers reference,blender)
expect_in("${err}" "holds cases validated with the renderers reference and povray; this run's are reference and blender")
