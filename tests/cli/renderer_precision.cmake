# A renderer definition file's `precision` (docs/renderer-file.md): the
# declared model is the renderer's (`xval renderers --json` shows it), a
# file without one gets gl's float32 model, and a malformed declaration is
# an error naming the file and the field (exit 2), never a silent default.
# Arguments: XVAL, STANDIN, WORK.
foreach(_v XVAL STANDIN WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "renderer_precision.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(COPY ${STANDIN} DESTINATION ${WORK})
function(definition file precision)
  file(WRITE ${WORK}/${file} "{\"format\": \"xval-renderer/1\", \"name\": \"mine\", \"input\": \"scene\",
 \"command\": [\"./standin_renderer.sh\", \"pass\", \"{scene}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./standin_renderer.sh\", \"--version\"]${precision}}\n")
endfunction()
function(precision_of file result)
  execute_process(COMMAND ${XVAL} renderers --renderer-file ${WORK}/${file} --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "xval renderers --renderer-file ${file}: exit ${rc}\n${err}")
  endif()
  string(JSON n LENGTH "${out}" renderers)
  math(EXPR last "${n} - 1")
  foreach(k RANGE ${last})
    string(JSON id GET "${out}" renderers ${k} id)
    if(id STREQUAL "mine")
      string(JSON p GET "${out}" renderers ${k} precision)
      set(${result} "${p}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "renderer mine not listed:\n${out}")
endfunction()

definition(declared.json ", \"precision\": {\"position_steps\": 0.25, \"uv_steps\": 0.5, \"normal_steps\": 0.001,
 \"relative\": 1e-6, \"quantum_16bit\": 0.5, \"basis\": \"measured on my engine\"}")
precision_of(declared.json p)
string(JSON pos GET "${p}" position_steps)
string(JSON q GET "${p}" quantum_16bit)
string(JSON basis GET "${p}" basis)
if(NOT pos EQUAL 0.25 OR NOT q EQUAL 0.5 OR NOT basis STREQUAL "measured on my engine")
  message(FATAL_ERROR "the declared model is not the renderer's: ${p}")
endif()

definition(none.json "")
precision_of(none.json p)
string(JSON basis GET "${p}" basis)
string(JSON pos GET "${p}" position_steps)
if(NOT basis MATCHES "default" OR NOT pos EQUAL 1)
  message(FATAL_ERROR "a file without precision does not get the float32 default: ${p}")
endif()

foreach(_case "missing basis|\"precision\": {\"position_steps\": 1, \"uv_steps\": 1, \"normal_steps\": 0, \"relative\": 0, \"quantum_16bit\": 0}|precision.basis"
              "negative steps|\"precision\": {\"position_steps\": -1, \"uv_steps\": 1, \"normal_steps\": 0, \"relative\": 0, \"quantum_16bit\": 0, \"basis\": \"x\"}|precision.position_steps"
              "unknown field|\"precision\": {\"position_steps\": 1, \"uv_steps\": 1, \"normal_steps\": 0, \"relative\": 0, \"quantum_16bit\": 0, \"basis\": \"x\", \"bits\": 8}|precision.bits")
  string(REPLACE "|" ";" _parts "${_case}")
  list(GET _parts 0 _what)
  list(GET _parts 1 _json)
  list(GET _parts 2 _field)
  definition(bad.json ", ${_json}")
  execute_process(COMMAND ${XVAL} renderers --renderer-file ${WORK}/bad.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2 OR NOT err MATCHES "bad.json" OR NOT err MATCHES "${_field}")
    message(FATAL_ERROR "${_what}: expected exit 2 naming bad.json and ${_field}; got exit ${rc}:\n${err}")
  endif()
endforeach()
message(STATUS "renderer precision: declared, default and malformed as expected")
