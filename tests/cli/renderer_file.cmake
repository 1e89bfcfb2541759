# A renderer defined by a file (docs/renderer-file.md), the stand-in
# standin_renderer.sh copied into a scratch folder beside its definition
# (the relative program path is resolved against the definition's folder).
# Each fault must be an error (exit 2 from `xval render`, exit 2 from
# `xval crosscheck`) naming the fault and quoting the stand-in's output,
# with no image written; `pass` must render and pass the crosscheck
# against the reference renderer.
# Arguments: XVAL, SCENE, STANDIN, WORK, MODE (pass, missing, fail, hang,
# no-image, wrong-size, two-channels, nan).
foreach(_v XVAL SCENE STANDIN WORK MODE)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "renderer_file.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)
set(_program ./standin_renderer.sh)
if(MODE STREQUAL "missing")
  set(_program ./no_such_renderer.sh)
endif()
set(_timeout "")
if(MODE STREQUAL "hang")
  set(_timeout ",\n \"timeout_s\": 2")
endif()
set(_def ${WORK}/def/standin.json)
file(WRITE ${_def} "{\"format\": \"xval-renderer/1\",
 \"name\": \"standin\",
 \"description\": \"a stand-in for a user's renderer\",
 \"input\": \"scene\",
 \"command\": [\"${_program}\", \"${MODE}\", \"{scene}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./standin_renderer.sh\", \"--version\"]${_timeout}}\n")

if(MODE STREQUAL "pass")
  set(_expect_render 0)
  set(_expect_cross 0)
  set(_message "")
else()
  set(_expect_render 2)
  set(_expect_cross 2)
  if(MODE STREQUAL "missing")
    set(_message "no_such_renderer.sh' of .*standin.json is not an executable file")
  else()
    if(MODE STREQUAL "fail")
      set(_message "exit code 3")
    elseif(MODE STREQUAL "hang")
      set(_message "timed out after 2 s")
    elseif(MODE STREQUAL "no-image")
      set(_message "exited 0 but wrote no image")
    elseif(MODE STREQUAL "wrong-size")
      set(_message "17x16.*expected 16x16")
    elseif(MODE STREQUAL "two-channels")
      set(_message "has 2 channel\\(s\\), expected at least 3")
    elseif(MODE STREQUAL "nan")
      set(_message "non-finite values \\(NaN or infinity\\) in 256 of 256 pixels")
    else()
      message(FATAL_ERROR "renderer_file.cmake: unknown MODE ${MODE}")
    endif()
    # Every fault after the program started quotes its output.
    string(APPEND _message ".*standin: mode ${MODE}")
    if(MODE STREQUAL "fail")
      string(APPEND _message ".*standin: the engine crashed")
    endif()
  endif()
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E env XVAL=${XVAL}
                  ${XVAL} render ${SCENE} -o ${WORK}/out.exr --renderer standin --renderer-file ${_def}
                  --work-dir ${WORK}/render -q
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err TIMEOUT 60)
if(NOT _rc EQUAL _expect_render)
  message(FATAL_ERROR "xval render (${MODE}): exit ${_rc}, expected ${_expect_render}\n${_out}\n${_err}")
endif()
if(_message AND NOT _err MATCHES "${_message}")
  message(FATAL_ERROR "xval render (${MODE}): the error does not match \"${_message}\":\n${_err}")
endif()
if(MODE STREQUAL "pass")
  if(NOT EXISTS ${WORK}/out.exr)
    message(FATAL_ERROR "xval render (pass): no image written")
  endif()
elseif(EXISTS ${WORK}/out.exr)
  message(FATAL_ERROR "xval render (${MODE}): an image was written although the renderer failed")
endif()

execute_process(COMMAND ${CMAKE_COMMAND} -E env XVAL=${XVAL}
                  ${XVAL} crosscheck ${SCENE} --renderer standin --renderer-file ${_def} -o ${WORK}/cross
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err TIMEOUT 60)
if(NOT _rc EQUAL _expect_cross)
  message(FATAL_ERROR "xval crosscheck (${MODE}): exit ${_rc}, expected ${_expect_cross}\n${_out}\n${_err}")
endif()
if(_message AND NOT _err MATCHES "${_message}")
  message(FATAL_ERROR "xval crosscheck (${MODE}): the error does not match \"${_message}\":\n${_err}")
endif()

# `xval renderers` lists it with its description and its version from
# version_command.
execute_process(COMMAND ${XVAL} renderers --renderer-file ${_def}
                RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err TIMEOUT 60)
if(NOT _rc EQUAL 0 OR NOT _out MATCHES "standin .*a stand-in for a user's renderer; defined by .*version: standin 1.0")
  message(FATAL_ERROR "xval renderers --renderer-file: exit ${_rc}\n${_out}\n${_err}")
endif()
