# `xval crosscheck --junit FILE`: the verdict as JUnit XML, valid against
# tests/junit/junit.xsd, for each outcome, with a stand-in POV-Ray:
#   - it writes the reference render: exit 0, one passing testcase;
#   - it writes that render darkened by 2%: exit 1, a <failure> naming the
#     tolerance;
#   - it fails (exit 9): exit 2, an <error> naming what happened.
# Each is validate's run of that one scene and pair (validate/validation/crosscheck.h):
# results.json holds the case, and metrics.json is its pair as written there.
# Arguments: XVAL, SCENE, XSD, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(crosscheck_junit.cmake XVAL SCENE XSD WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin)
find_program(_oiiotool oiiotool REQUIRED)
run(0 ${XVAL} render ${SCENE} -o ${WORK}/ref.exr --precision double -q)

function(povray_stand_in make)
  file(WRITE ${WORK}/bin/povray
    "#!/bin/sh\nif [ \"$1\" = --version ]; then echo 'stand-in povray 0.0'; exit 0; fi\n"
    "out=$(/bin/sed -n 's/^Output_File_Name=//p' scene.ini)\nfor a in \"$@\"; do o=$(echo \"$a\" | /bin/sed -n 's/^+O//p'); [ -z \"$o\" ] || out=$o; done\n${make}\n")
  file(CHMOD ${WORK}/bin/povray PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()

function(crosscheck_case name expect_rc)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "PATH=${WORK}/bin:/usr/bin:/bin"
                          ${XVAL} crosscheck ${SCENE} --renderer povray -o ${WORK}/${name} --timeout 60
                          --junit ${WORK}/${name}.xml
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
  message("${name}: exit ${rc}\n${out}${err}")
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "${name}: exit status ${rc}, expected ${expect_rc}")
  endif()
  execute_process(COMMAND xmllint --noout --schema ${XSD} ${WORK}/${name}.xml
                  RESULT_VARIABLE _rc ERROR_VARIABLE _lint)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${name}.xml is not valid against ${XSD} (xmllint exit ${_rc}):\n${_lint}")
  endif()
  file(READ ${WORK}/${name}.xml _x)
  expect_in("${_x}" "classname=\"tiny\" name=\"reference-povray\"")
  set(xml "${_x}" PARENT_SCOPE)
endfunction()

povray_stand_in("/bin/cp '${WORK}/ref.exr' \"$out\"")
crosscheck_case(pass 0)
expect_in("${xml}" "tests=\"1\" failures=\"0\" errors=\"0\" skipped=\"0\"")
function(expect_validate_run name verdict)
  file(READ ${WORK}/${name}/results.json _r)
  get_json(_renderers "${_r}" renderers)
  expect_eq("${name}: results.json renderers" "${_renderers}" "[ \"reference\", \"povray\" ]")
  get_json(_pair "${_r}" cases 0 pairs 0 pair)
  expect_eq("${name}: results.json pair" "${_pair}" "reference-povray")
  get_json(_v "${_r}" cases 0 pairs 0 verdict)
  expect_eq("${name}: results.json verdict" "${_v}" "${verdict}")
  file(READ ${WORK}/${name}/metrics.json _m)
  get_json(_v "${_m}" verdict)
  expect_eq("${name}: metrics.json verdict" "${_v}" "${verdict}")
endfunction()
expect_validate_run(pass pass)

povray_stand_in("'${_oiiotool}' '${WORK}/ref.exr' --mulc 0.98,0.98,0.98,1 -d float -o \"$out.exr\" && /bin/mv \"$out.exr\" \"$out\"")
crosscheck_case(fail 1)
expect_in("${xml}" "tests=\"1\" failures=\"1\" errors=\"0\"")
expect_in("${xml}" "<failure message=\"outside the tolerance: ")
expect_validate_run(fail fail)

povray_stand_in("echo 'stand-in trouble' >&2; exit 9")
crosscheck_case(error 2)
expect_in("${xml}" "tests=\"1\" failures=\"0\" errors=\"1\"")
expect_in("${xml}" "<error message=\"")
