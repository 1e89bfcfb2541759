# Hostile inputs to validate's records, compare step and report (issue #34):
#   bad-bytes       a renderer whose log holds bytes that are no UTF-8 and
#                   whose quoted tail starts inside a character, exiting 3:
#                   its error is recorded (valid UTF-8, U+FFFD for the bad
#                   bytes), results.json and the report are written, exit 2;
#   replaced-image  an image replaced, after its record said ok, by one of
#                   another size: --compare-only makes that case an error
#                   naming the file, compares the other case, writes
#                   results.json and the report, exit 2;
#   pair-ids        renderer files named m-n, reference-m and n: six
#                   distinct pair ids; m-z, reference-m and z (pairs
#                   reference + m-z and reference-m + z would share the id
#                   reference-m-z): refused naming the files, exit 2;
#   missing-fields  every field docs/results-schema.json requires, removed
#                   from a real results.json in turn: `xval report` exits 2
#                   naming the file and the field (no crash, no library
#                   message).
# Arguments: XVAL, SCENE (tests/cli/scenes/tiny.json), STANDIN
# (standin_renderer.sh), SCHEMA (docs/results-schema.json), WORK, MODE.
foreach(_v XVAL SCENE STANDIN SCHEMA WORK MODE)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "hostile_results.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def ${WORK}/scenes)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

# A renderer file for the stand-in: NAME, running the stand-in's MODE.
function(standin_file name mode out_var)
  set(_f ${WORK}/def/${name}.json)
  file(WRITE ${_f} "{\"format\": \"xval-renderer/1\", \"name\": \"${name}\", \"input\": \"scene\",
 \"command\": [\"./standin_renderer.sh\", \"${mode}\", \"{scene}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./standin_renderer.sh\", \"--version\"]}\n")
  set(${out_var} ${_f} PARENT_SCOPE)
endfunction()

# Two scenes: tiny and a copy named twin.
file(COPY ${SCENE} DESTINATION ${WORK}/scenes)
file(READ ${SCENE} _text)
string(REPLACE "\"name\": \"tiny\"" "\"name\": \"twin\"" _text "${_text}")
file(WRITE ${WORK}/scenes/twin.json "${_text}")
set(_scenes ${WORK}/scenes/tiny.json ${WORK}/scenes/twin.json)

if(MODE STREQUAL "bad-bytes")
  standin_file(standin bad-bytes _def)
  run_xval(2 _o validate ${WORK}/scenes/tiny.json --renderers reference,standin --renderer-file ${_def}
           -o ${WORK}/run)
  if(_o MATCHES "json.exception|cannot be written")
    message(FATAL_ERROR "the record or results were not written:\n${_o}")
  endif()
  foreach(_f results.json report.html tiny/standin.job.json)
    if(NOT EXISTS ${WORK}/run/${_f})
      message(FATAL_ERROR "no ${_f} written:\n${_o}")
    endif()
  endforeach()
  file(READ ${WORK}/run/results.json _r)
  string(JSON _err GET "${_r}" cases 0 renders standin error)
  expect("${_err}" "exit code 3" "the renderer's error in results.json")
  # The bad bytes as U+FFFD, the cut tail from a whole euro sign on.
  expect("${_err}" "\\| \\[\\.\\.\\. cut: [^\n]*\\] €€" "the tail cut on a character boundary")
  expect("${_err}" "\\| �� end" "the bytes 0xFF 0xFE as U+FFFD")
  string(JSON _v GET "${_r}" cases 0 verdict)
  expect("${_v}" "^error$" "the case's verdict")
elseif(MODE STREQUAL "replaced-image")
  standin_file(standin pass _def)
  run_xval(0 _o validate ${_scenes} --renderers reference,standin --renderer-file ${_def} -o ${WORK}/run)
  # tiny's stand-in image becomes an 8x8 one; its record still says ok.
  execute_process(COMMAND oiiotool --create 8x8 4 -d float -o ${WORK}/run/tiny/standin.exr RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "oiiotool: ${_rc}")
  endif()
  file(REMOVE ${WORK}/run/results.json ${WORK}/run/report.html)
  run_xval(2 _o validate --plan ${WORK}/run/jobs.json --compare-only)
  foreach(_f results.json report.html)
    if(NOT EXISTS ${WORK}/run/${_f})
      message(FATAL_ERROR "no ${_f} written:\n${_o}")
    endif()
  endforeach()
  file(READ ${WORK}/run/results.json _r)
  string(JSON _scene GET "${_r}" cases 0 scene)
  string(JSON _v GET "${_r}" cases 0 verdict)
  string(JSON _err GET "${_r}" cases 0 pairs 0 error)
  expect("${_scene} ${_v}" "^tiny error$" "the case with the replaced image")
  expect("${_err}" "${WORK}/run/tiny/standin.exr \\(8x8\\)" "the pair's error names the replaced file")
  string(JSON _scene GET "${_r}" cases 1 scene)
  string(JSON _v GET "${_r}" cases 1 verdict)
  expect("${_scene} ${_v}" "^twin pass$" "the other case, compared")
elseif(MODE STREQUAL "pair-ids")
  # m-n, reference-m and n: in registry order (built-in, then users' by
  # name: m-n, n, reference-m) their pairs are reference-m-n and
  # n-reference-m, six distinct ids, and the run goes ahead.
  standin_file(m-n pass _a)
  standin_file(reference-m pass _b)
  standin_file(n pass _c)
  run_xval(0 _o validate ${WORK}/scenes/tiny.json --renderers reference,m-n,reference-m,n
           --renderer-file ${_a} --renderer-file ${_b} --renderer-file ${_c} -o ${WORK}/run)
  file(READ ${WORK}/run/results.json _r)
  set(_ids)
  foreach(_i RANGE 5)
    string(JSON _id GET "${_r}" cases 0 pairs ${_i} pair)
    list(APPEND _ids ${_id})
  endforeach()
  list(REMOVE_DUPLICATES _ids)
  list(LENGTH _ids _n)
  expect("${_n}" "^6$" "six distinct pair ids (${_ids})")
  # m-z, reference-m and z: reference + m-z and reference-m + z would both
  # be reference-m-z: refused, naming the files.
  standin_file(m-z pass _a)
  standin_file(z pass _c)
  run_xval(2 _o validate ${WORK}/scenes/tiny.json --renderers reference,m-z,reference-m,z
           --renderer-file ${_a} --renderer-file ${_b} --renderer-file ${_c} -o ${WORK}/clash --plan-only)
  expect("${_o}" "${_a}: name \"m-z\"" "the error names m-z's file")
  expect("${_o}" "${_b}: name \"reference-m\"" "the error names reference-m's file")
  expect("${_o}" "${_c}: name \"z\"" "the error names z's file")
  expect("${_o}" "reference \\+ m-z and reference-m \\+ z would both be named \"reference-m-z\""
         "the error names the pairs")
  if(EXISTS ${WORK}/clash/jobs.json)
    message(FATAL_ERROR "a plan was written for renderers whose pairs share an id")
  endif()
elseif(MODE STREQUAL "missing-fields")
  standin_file(standin pass _def)
  run_xval(0 _o validate ${_scenes} --renderers reference,standin --renderer-file ${_def} -o ${WORK}/run)
  file(READ ${WORK}/run/results.json _real)
  run_xval(0 _o report ${WORK}/run/results.json -o ${WORK}/run/check.html)
  file(READ ${SCHEMA} _schema)
  # Each field the schema requires (following $ref and items into arrays'
  # first entry), wherever the real results.json has it: removed, the
  # report must name it. _walk(JSON path... schema path...).
  set_property(GLOBAL PROPERTY _checked 0)
  function(_walk json_path schema_node)
    string(JSON _type ERROR_VARIABLE _e TYPE "${_real}" ${json_path})
    if(_e)
      return()
    endif()
    string(JSON _ref ERROR_VARIABLE _e GET "${schema_node}" "$ref")
    if(NOT _e)
      string(REPLACE "#/definitions/" "" _name "${_ref}")
      string(JSON schema_node GET "${_schema}" definitions ${_name})
    endif()
    if(_type STREQUAL "ARRAY")
      string(JSON _items ERROR_VARIABLE _e GET "${schema_node}" items)
      string(JSON _n LENGTH "${_real}" ${json_path})
      if(NOT _e AND _n GREATER 0)
        _walk("${json_path};0" "${_items}")
      endif()
      return()
    endif()
    if(NOT _type STREQUAL "OBJECT")
      return()
    endif()
    string(JSON _req ERROR_VARIABLE _e GET "${schema_node}" required)
    if(NOT _e)
      string(JSON _nreq LENGTH "${_req}")
      math(EXPR _last "${_nreq} - 1")
      foreach(_i RANGE ${_last})
        string(JSON _key GET "${_req}" ${_i})
        string(JSON _has ERROR_VARIABLE _e TYPE "${_real}" ${json_path} ${_key})
        if(_e)
          continue()
        endif()
        string(JSON _cut REMOVE "${_real}" ${json_path} ${_key})
        file(WRITE ${WORK}/run/cut.json "${_cut}")
        execute_process(COMMAND ${XVAL} report ${WORK}/run/cut.json -o ${WORK}/run/cut.html
                        RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out TIMEOUT 60)
        # The field as the report names it: a.b[0].c.
        set(_field "")
        foreach(_p ${json_path} ${_key})
          if(_p MATCHES "^[0-9]+$")
            string(APPEND _field "\\[${_p}\\]")
          elseif(_field STREQUAL "")
            string(APPEND _field "${_p}")
          else()
            string(APPEND _field "\\.${_p}")
          endif()
        endforeach()
        if(NOT _rc EQUAL 2 OR NOT _out MATCHES "cut.json: ${_field}: missing \\(expected"
           OR _out MATCHES "json.exception")
          message(FATAL_ERROR "results.json without ${json_path} ${_key}: exit ${_rc}, expected 2 naming "
                              "\"cut.json: ${_field}: missing\":\n${_out}")
        endif()
        get_property(_c GLOBAL PROPERTY _checked)
        math(EXPR _c "${_c} + 1")
        set_property(GLOBAL PROPERTY _checked ${_c})
      endforeach()
    endif()
    string(JSON _props ERROR_VARIABLE _e GET "${schema_node}" properties)
    if(_e)
      set(_props "{}")
    endif()
    string(JSON _extra ERROR_VARIABLE _e GET "${schema_node}" additionalProperties)
    if(_e OR NOT _extra MATCHES "^{")
      set(_extra "")
    endif()
    string(JSON _nkeys LENGTH "${_real}" ${json_path})
    if(_nkeys EQUAL 0)
      return()
    endif()
    math(EXPR _last "${_nkeys} - 1")
    foreach(_i RANGE ${_last})
      string(JSON _key MEMBER "${_real}" ${json_path} ${_i})
      string(JSON _sub ERROR_VARIABLE _e GET "${_props}" ${_key})
      if(_e)
        set(_sub "${_extra}")
      endif()
      if(NOT _sub STREQUAL "")
        _walk("${json_path};${_key}" "${_sub}")
      endif()
    endforeach()
  endfunction()
  _walk("" "${_schema}")
  get_property(_checked GLOBAL PROPERTY _checked)
  message("removed ${_checked} required fields in turn")
  if(_checked LESS 40)
    message(FATAL_ERROR "only ${_checked} required fields were removed: the walk missed the cases")
  endif()
else()
  message(FATAL_ERROR "hostile_results.cmake: unknown MODE ${MODE}")
endif()
