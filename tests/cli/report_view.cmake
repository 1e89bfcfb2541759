# The report is a view of results.json and the files it names
# (validate/report/report.h):
#   - `xval validate` on a small scene, with stand-in POV-Ray and Blender
#     that write the reference render (Blender's darkened by 2%; one scene
#     per Blender process, --batch 1: the stand-in speaks only that
#     protocol), writes a
#     heat map per pair and names it in results.json; with --junit, a JUnit
#     XML file valid against tests/junit/junit.xsd (2 failures of 3 pairs);
#   - `xval report` on a copy of the output folder without any EXR (as a
#     fresh clone has it) keeps every heat map byte for byte, references
#     each one, and shows the paper-claim verdicts stored in results.json
#     (here a verdict put there by the test); a heat map that is gone is
#     said to be missing, not regenerated.
# Arguments: XVAL, SCENE, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(report_view.cmake XVAL SCENE XSD WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin)
find_program(_oiiotool oiiotool REQUIRED)

run(0 ${XVAL} render ${SCENE} -o ${WORK}/ref.exr --precision double -q)
# The stand-ins write an EXR at the path the real tool would (POV-Ray: the
# Output_File_Name of scene.ini; Blender: --out); OpenImageIO reads it by
# its content.
function(stand_in tool find make)
  file(WRITE ${WORK}/bin/${tool}
    "#!/bin/sh\nif [ \"$1\" = --version ]; then echo 'stand-in ${tool} 0.0'; exit 0; fi\n${find}\n${make}\n")
  file(CHMOD ${WORK}/bin/${tool} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()
stand_in(povray "out=$(/bin/sed -n 's/^Output_File_Name=//p' scene.ini)\nfor a in \"$@\"; do o=$(echo \"$a\" | /bin/sed -n 's/^+O//p'); [ -z \"$o\" ] || out=$o; done"
         "/bin/cp '${WORK}/ref.exr' \"$out\"")
stand_in(blender "while [ $# -gt 0 ]; do if [ \"$1\" = --out ]; then out=$2; fi; shift; done"
         "'${_oiiotool}' '${WORK}/ref.exr' --mulc 0.98,0.98,0.98,1 -d float -o \"$out.exr\" && /bin/mv \"$out.exr\" \"$out\"")

execute_process(COMMAND ${CMAKE_COMMAND} -E env "PATH=${WORK}/bin:/usr/bin:/bin"
                        ${XVAL} validate ${SCENE} -o ${WORK}/out --jobs 2 --timeout 60 --batch 1 --junit ${WORK}/junit.xml
                        --renderers reference,povray,blender
                RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 300)
message("xval validate: exit ${rc}\n${err}")
if(NOT rc EQUAL 0 AND NOT rc EQUAL 1)
  message(FATAL_ERROR "xval validate exited ${rc}, expected a verdict (0 or 1)")
endif()
expect_in("${err}" "tolerances: ")  # the tolerance file used is said

# --junit: one testcase per pair, valid against tests/junit/junit.xsd; the
# Blender stand-in (colour x 0.98) fails its pairs, POV-Ray's passes.
expect_valid_junit(${WORK}/junit.xml ${XSD})
file(READ ${WORK}/junit.xml _junit)
expect_in("${_junit}" "tests=\"3\" failures=\"2\" errors=\"0\"")
expect_in("${_junit}" "name=\"reference-blender\"")
expect_in("${_junit}" "<failure message=\"outside the tolerance: ")

# The published form: no EXR, no work folders, no plan or job records.
file(COPY ${WORK}/out/ DESTINATION ${WORK}/copy
     PATTERN "*.exr" EXCLUDE PATTERN "*.work" EXCLUDE PATTERN "*.job.json" EXCLUDE
     PATTERN "jobs.json" EXCLUDE PATTERN "report.html" EXCLUDE)
file(GLOB_RECURSE _exrs ${WORK}/copy/*.exr)
if(_exrs)
  message(FATAL_ERROR "the copy holds EXRs: ${_exrs}")
endif()

file(READ ${WORK}/copy/results.json _results)
string(JSON _case GET "${_results}" cases 0)
string(JSON _npairs LENGTH "${_case}" pairs)
if(NOT _npairs EQUAL 3)
  message(FATAL_ERROR "expected 3 pairs, results.json has ${_npairs}")
endif()
set(_maps "")
math(EXPR _last "${_npairs} - 1")
foreach(_i RANGE ${_last})
  string(JSON _map ERROR_VARIABLE _no GET "${_case}" pairs ${_i} heat_map)
  if(_no)
    message(FATAL_ERROR "pair ${_i} of results.json names no heat map: ${_no}")
  endif()
  if(NOT EXISTS ${WORK}/copy/${_map})
    message(FATAL_ERROR "the heat map results.json names, ${_map}, was not written by validate")
  endif()
  file(MD5 ${WORK}/copy/${_map} _md5_${_i})
  list(APPEND _maps ${_map})
endforeach()

# A verdict only results.json knows.
string(JSON _results SET "${_results}" paper_claims
  [=[{"scenes": ["tiny"], "claims": [{"claim": "A claim only results.json states", "condition": "as stored",
      "measured": "12.5 units", "holds": false}]}]=])
file(WRITE ${WORK}/copy/results.json "${_results}")

run(0 ${XVAL} report ${WORK}/copy/results.json)
file(READ ${WORK}/copy/report.html _html)
set(_i 0)
foreach(_map ${_maps})
  file(MD5 ${WORK}/copy/${_map} _after)
  if(NOT _after STREQUAL _md5_${_i})
    message(FATAL_ERROR "xval report rewrote ${_map}")
  endif()
  expect_in("${_html}" "<img class=\"heat\" src=\"${_map}\"")
  math(EXPR _i "${_i} + 1")
endforeach()
expect_in("${_html}" "A claim only results.json states")
expect_in("${_html}" "12.5 units")
expect_in("${_html}" "does not hold")
file(GLOB_RECURSE _exrs ${WORK}/copy/*.exr)
if(_exrs)
  message(FATAL_ERROR "xval report wrote EXRs: ${_exrs}")
endif()

# A heat map that is gone is said to be missing, never made anew.
list(GET _maps 0 _gone)
file(REMOVE ${WORK}/copy/${_gone})
run(0 ${XVAL} report ${WORK}/copy/results.json)
file(READ ${WORK}/copy/report.html _html)
expect_in("${_html}" "heat map ${_gone} (named in results.json) is missing")
if(EXISTS ${WORK}/copy/${_gone})
  message(FATAL_ERROR "xval report regenerated ${_gone}")
endif()
