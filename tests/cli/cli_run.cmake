# Helpers shared by the CLI test scripts run with `cmake -P`.
#
# require_defined(SCRIPT VAR...): fails unless every -DVAR=... was given.
# run(EXPECT_RC COMMAND...): runs COMMAND (at most 60 s), prints it with its
#   exit status and stderr, fails unless it exits EXPECT_RC or if stderr
#   shows a crash or a sanitizer report; sets `err` (its stderr) and `out`
#   (its stdout) in the caller.
# expect_in(TEXT WHAT): fails unless TEXT contains WHAT.
# expect_eq(WHAT GOT WANT): fails, naming WHAT, unless GOT equals WANT.
# get_json(VAR JSON KEY...): VAR = the member of the JSON text at the keys
#   and indices given; fails, naming them, when it is absent.
# write_povray_stand_in(BIN MAKE): BIN/povray, a stand-in that answers
#   --version and otherwise runs the shell text MAKE with $out set to the
#   image path the real POV-Ray would write (scene.ini's Output_File_Name,
#   or a +O argument).
# write_standin_renderer(DIR NAME MODE): DIR/NAME.json, a renderer file
#   (docs/renderer-file.md) of renderer NAME that runs the stand-in
#   DIR/standin_renderer.sh (tests/cli) in MODE.
# expect_valid_junit(FILE XSD): fails unless xmllint finds FILE valid
#   against the schema XSD (tests/junit/junit.xsd); a missing xmllint fails.
function(require_defined script)
  foreach(_v ${ARGN})
    if(NOT DEFINED ${_v})
      message(FATAL_ERROR "${script}: -D${_v}=... is required")
    endif()
  endforeach()
endfunction()

function(run expect_rc)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  message("command: ${ARGN}\nexit: ${rc}\nstderr:\n${err}")
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "exit status ${rc}, expected ${expect_rc}")
  endif()
  foreach(_s "AddressSanitizer" "runtime error:" "terminate called")
    string(FIND "${err}" "${_s}" _at)
    if(NOT _at EQUAL -1)
      message(FATAL_ERROR "stderr shows a crash or sanitizer report (\"${_s}\")")
    endif()
  endforeach()
  set(err "${err}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
endfunction()

# `xval validate ARGN` with the stand-in tools of folder `bin` first on PATH
# (write_povray_stand_in): its exit status must be expect_rc; its stderr
# into err.
function(validate_with_stand_ins expect_rc bin)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env "PATH=${bin}:/usr/bin:/bin" ${XVAL} validate ${ARGN}
                  RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 300)
  message("xval validate ${ARGN}: exit ${rc}\n${err}")
  if(NOT rc EQUAL expect_rc)
    message(FATAL_ERROR "xval validate exited ${rc}, expected ${expect_rc}")
  endif()
  set(err "${err}" PARENT_SCOPE)
endfunction()

# For each name of ARGN: ${WORK}/scenes/<name>.json, the scene file SCENE
# (named "tiny") renamed <name>, and its reference render
# ${WORK}/ref_<name>.exr, for a stand-in renderer to copy.
function(write_renamed_scenes)
  file(READ ${SCENE} _tiny)
  foreach(_s ${ARGN})
    string(REPLACE "\"name\": \"tiny\"" "\"name\": \"${_s}\"" _text "${_tiny}")
    file(WRITE ${WORK}/scenes/${_s}.json "${_text}")
    run(0 ${XVAL} render ${WORK}/scenes/${_s}.json -o ${WORK}/ref_${_s}.exr --precision double -q)
  endforeach()
endfunction()

function(expect_in text what)
  string(FIND "${text}" "${what}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "does not say \"${what}\"")
  endif()
endfunction()

function(expect_eq what got want)
  if(NOT "${got}" STREQUAL "${want}")
    message(FATAL_ERROR "${what}: \"${got}\", expected \"${want}\"")
  endif()
endfunction()

function(get_json var json)
  string(JSON _v ERROR_VARIABLE _no GET "${json}" ${ARGN})
  if(_no)
    message(FATAL_ERROR "results.json: ${ARGN}: ${_no}")
  endif()
  set(${var} "${_v}" PARENT_SCOPE)
endfunction()

function(write_povray_stand_in bin make)
  file(WRITE ${bin}/povray
    "#!/bin/sh\nif [ \"$1\" = --version ]; then echo 'stand-in povray 0.0'; exit 0; fi\n"
    "out=$(/bin/sed -n 's/^Output_File_Name=//p' scene.ini)\n"
    "for a in \"$@\"; do o=$(echo \"$a\" | /bin/sed -n 's/^+O//p'); [ -z \"$o\" ] || out=$o; done\n"
    "${make}\n")
  file(CHMOD ${bin}/povray PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()

function(write_standin_renderer dir name mode)
  file(WRITE ${dir}/${name}.json "{\"format\": \"xval-renderer/1\",
 \"name\": \"${name}\",
 \"input\": \"scene\",
 \"command\": [\"./standin_renderer.sh\", \"${mode}\", \"{scene}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./standin_renderer.sh\", \"--version\"]}\n")
endfunction()

function(expect_valid_junit file xsd)
  execute_process(COMMAND xmllint --noout --schema ${xsd} ${file} RESULT_VARIABLE _rc ERROR_VARIABLE _lint)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${file} is not valid against ${xsd} (xmllint exit ${_rc}):\n${_lint}")
  endif()
endfunction()
