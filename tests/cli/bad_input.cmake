# One bad input through the xval command line, checked as the user sees it:
#   - the exit status is a number (not a signal) and is EXIT (non-zero);
#   - no sanitizer report (under XVAL_SANITIZE a sanitizer also exits 1);
#   - stderr contains the input file's name and every string of EXPECT
#     (the field path, the bad value, what was expected);
#   - nothing named in NOT_CREATED exists afterwards.
# Arguments: XVAL, INPUT (file; or PREPARE=<kind> to make it under WORK),
# WORK (scratch folder), EXIT, EXPECT (;-list), optional MODE (render,
# generate, validate, bench, tradeoff, export or crosscheck; default render),
# ARGS (|-list of extra arguments), NOT_CREATED (;-list of paths).
foreach(_v XVAL WORK EXIT EXPECT)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "bad_input.cmake: -D${_v}=... is required")
  endif()
endforeach()
if(NOT DEFINED MODE)
  set(MODE render)
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Inputs made here rather than kept in the source tree.
if(PREPARE STREQUAL "nesting_bomb")
  # 100000 nested arrays in one field (a recursive parser or printer
  # overflows its stack on this).
  string(REPEAT "[" 100000 _open)
  string(REPEAT "]" 100000 _close)
  set(INPUT ${WORK}/nesting_bomb.json)
  file(WRITE ${INPUT} "{\"camera\": {\"position\": ${_open}${_close}}}\n")
elseif(PREPARE STREQUAL "oversize")
  # A 65 MiB scene file (sparse: costs no disk).
  set(INPUT ${WORK}/oversize.json)
  file(WRITE ${INPUT} "{\"name\": \"x\"}\n")
  execute_process(COMMAND truncate -s 65M ${INPUT} RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "truncate failed: ${_rc}")
  endif()
elseif(PREPARE STREQUAL "texture_is_a_directory")
  # The texture path names a folder (tests run as root, so a file without
  # read permission would still be readable: a folder is what cannot be).
  set(INPUT ${WORK}/texture_is_a_directory.json)
  file(MAKE_DIRECTORY ${WORK}/texture_dir.png)
  file(WRITE ${INPUT} "{\"camera\": {\"position\": [0, 0, 4], \"target\": [0, 0, 0]},
 \"objects\": [{\"shape\": \"sphere\"}],
 \"material\": {\"model\": {\"type\": \"lambert\"},
              \"texture\": {\"source\": \"image\", \"path\": \"texture_dir.png\"}},
 \"lights\": []}\n")
elseif(PREPARE STREQUAL "many_objects")
  # 1000 objects, each at the per-mesh maximum (16777216 vertices: 4095 x
  # 4095 segments), in a 100 KB file: 33 billion triangles in all.
  set(INPUT ${WORK}/many_objects.json)
  string(REPEAT "{\"shape\": \"sphere\", \"segments_longitude\": 4095, \"segments_latitude\": 4095}, " 999 _objs)
  file(WRITE ${INPUT} "{\"camera\": {\"position\": [0, 0, 4], \"target\": [0, 0, 0], \"width\": 16, \"height\": 16},
 \"objects\": [${_objs}{\"shape\": \"sphere\"}],
 \"material\": {\"model\": {\"type\": \"lambert\"}}, \"lights\": []}\n")
elseif(DEFINED PREPARE)
  message(FATAL_ERROR "bad_input.cmake: unknown PREPARE=${PREPARE}")
endif()

if(MODE STREQUAL "render")
  set(_cmd ${XVAL} render ${INPUT} -o ${WORK}/out.exr -q)
elseif(MODE STREQUAL "generate")
  set(_cmd ${XVAL} generate ${INPUT} -o ${WORK}/out)
elseif(MODE STREQUAL "bench")
  set(_cmd ${XVAL} bench ${INPUT} --frames 1 --runs 1 --renderers reference)
elseif(MODE STREQUAL "tradeoff")
  set(_cmd ${XVAL} tradeoff ${INPUT} -o ${WORK}/out --quick --frames 1)
elseif(MODE STREQUAL "export")
  set(_cmd ${XVAL} export pov ${INPUT} -o ${WORK}/out)
elseif(MODE STREQUAL "crosscheck")
  set(_cmd ${XVAL} crosscheck ${INPUT} --renderer povray -o ${WORK}/out --timeout 5)
elseif(MODE STREQUAL "validate")
  set(_cmd ${XVAL} validate ${INPUT} -o ${WORK}/out --jobs 1 --timeout 5
           --tolerances ${CMAKE_CURRENT_LIST_DIR}/../../reference/tolerances.json)
else()
  message(FATAL_ERROR "bad_input.cmake: unknown MODE=${MODE}")
endif()
if(DEFINED ARGS)
  string(REPLACE "|" ";" ARGS "${ARGS}")
  list(APPEND _cmd ${ARGS})
endif()
execute_process(COMMAND ${_cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("command: ${_cmd}\nexit: ${rc}\nstderr:\n${err}")

if(NOT rc MATCHES "^[0-9]+$")
  message(FATAL_ERROR "xval did not exit normally: ${rc}")
endif()
if(NOT rc EQUAL EXIT)
  message(FATAL_ERROR "exit status ${rc}, expected ${EXIT}")
endif()
foreach(_s "AddressSanitizer" "LeakSanitizer" "runtime error:" "terminate called")
  string(FIND "${err}" "${_s}" _at)
  if(NOT _at EQUAL -1)
    message(FATAL_ERROR "stderr shows a crash or sanitizer report (\"${_s}\")")
  endif()
endforeach()
get_filename_component(_name ${INPUT} NAME)
string(REPLACE "|" ";" EXPECT "${EXPECT}")
string(REPLACE "|" ";" NOT_CREATED "${NOT_CREATED}")
foreach(_s ${_name} ${EXPECT})
  string(FIND "${err}" "${_s}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "stderr does not name \"${_s}\"")
  endif()
endforeach()
foreach(_p ${NOT_CREATED})
  if(EXISTS ${_p})
    message(FATAL_ERROR "${_p} was created")
  endif()
endforeach()
