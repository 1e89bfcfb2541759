# A scene's finding (docs/scene-format.md, `findings`), end to end through
# `xval validate`: a renderer whose built-in model is declared to differ.
# Two users' renderers by file (tests/cli/standin_renderer.sh): `kilo`
# halves the reference's image (it differs), `alpha` hands the scene to the
# reference renderer (it agrees).
#   1. kilo with a finding: the pair reference-kilo is outside its
#      tolerance as declared, so its verdict is `finding`, the case passes
#      (exit 0), results.json holds the finding, JUnit a passing testcase
#      with the finding, the report the FINDING cell and the measured note;
#   2. alpha with a finding: it agrees, so the finding no longer holds: the
#      pair fails, the case fails (exit 1), every view says so;
#   3. kilo without a finding: an ordinary failure (the finding is what
#      made 1 pass).
# Arguments: XVAL, SCENE (tiny, no `renderers`), STANDIN, XSD, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(findings.cmake XVAL SCENE STANDIN XSD WORK)
get_filename_component(XVAL ${XVAL} ABSOLUTE)  # the stand-in runs it from its work folder
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def ${WORK}/scenes)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)
write_standin_renderer(${WORK}/def alpha pass)
write_standin_renderer(${WORK}/def kilo dim)
file(READ ${SCENE} _tiny)

# The scene meant for the reference and `who`, with a finding for it
# (`finding` non-empty) or none.
function(scene_for who finding)
  set(_extra "\"renderers\": [\"reference\", \"${who}\"]")
  if(finding)
    string(APPEND _extra ", \"findings\": {\"${who}\": \"${finding}\"}")
  endif()
  string(REPLACE "\"name\": \"tiny\"" "\"name\": \"tiny\", ${_extra}" _text "${_tiny}")
  if(_text STREQUAL _tiny)
    message(FATAL_ERROR "findings.cmake: could not name the renderers in ${SCENE}")
  endif()
  file(WRITE ${WORK}/scenes/tiny.json "${_text}")
endfunction()

function(validate rc out who)
  run(${rc} ${CMAKE_COMMAND} -E env XVAL=${XVAL} ${XVAL} validate ${WORK}/scenes/tiny.json -o ${out} --timeout 60
      --renderers reference,${who} --renderer-file ${WORK}/def/${who}.json --junit ${out}.xml)
  set(err "${err}" PARENT_SCOPE)
endfunction()

set(_why "kilo renders at half the light, by design of this test")

# 1. The finding holds.
scene_for(kilo "${_why}")
validate(0 ${WORK}/holds kilo)
expect_in("${err}" "xval validate: 1 scene, all pass; wrote")
file(READ ${WORK}/holds/results.json _r)
get_json(_v "${_r}" cases 0 attribution)
expect_in("${_v}" "kilo differs as the scene's finding declares")
get_json(_v "${_r}" cases 0 pairs 0 verdict)
expect_eq("reference-kilo's verdict" "${_v}" "finding")
get_json(_v "${_r}" cases 0 pairs 0 finding renderer)
expect_eq("the finding's renderer" "${_v}" "kilo")
get_json(_v "${_r}" cases 0 pairs 0 finding why)
expect_eq("the finding's reason" "${_v}" "${_why}")
get_json(_v "${_r}" cases 0 pairs 0 pass)
expect_eq("reference-kilo within the tolerance" "${_v}" "OFF")
get_json(_v "${_r}" cases 0 verdict)
expect_eq("the case's verdict" "${_v}" "pass")
expect_valid_junit(${WORK}/holds.xml ${XSD})
file(READ ${WORK}/holds.xml _junit)
expect_in("${_junit}" "failures=\"0\" errors=\"0\"")
expect_in("${_junit}" "<system-out>finding of kilo: ${_why}; outside the tolerance as declared: ")
file(READ ${WORK}/holds/report.html _html)
expect_in("${_html}" "class=\"l find\">FINDING of kilo, p99.9 ")
expect_in("${_html}" "${_why} Measured: p99.9 ")

# 2. The finding no longer holds: alpha agrees.
scene_for(alpha "alpha is declared to differ, but it agrees")
validate(1 ${WORK}/gone alpha)
expect_in("${err}" "xval validate: 1 scene, FAIL")
file(READ ${WORK}/gone/results.json _r)
get_json(_v "${_r}" cases 0 pairs 0 verdict)
expect_eq("reference-alpha's verdict" "${_v}" "fail")
get_json(_v "${_r}" cases 0 pairs 0 pass)
expect_eq("reference-alpha within the tolerance" "${_v}" "ON")
get_json(_v "${_r}" cases 0 verdict)
expect_eq("the case's verdict" "${_v}" "fail")
expect_valid_junit(${WORK}/gone.xml ${XSD})
file(READ ${WORK}/gone.xml _junit)
expect_in("${_junit}" "type=\"finding_no_longer_holds\"")
expect_in("${_junit}" "the finding of alpha no longer holds (within the tolerance): ")
file(READ ${WORK}/gone/report.html _html)
expect_in("${_html}" "FAIL the finding of alpha no longer holds")

# 3. No finding: kilo simply fails.
scene_for(kilo "")
validate(1 ${WORK}/none kilo)
file(READ ${WORK}/none/results.json _r)
get_json(_v "${_r}" cases 0 pairs 0 verdict)
expect_eq("reference-kilo's verdict without a finding" "${_v}" "fail")
