# README.md's "Your first scene", run as written (label `cross`: POV-Ray
# and Blender). The commands are read from the README's section, not
# copied here, so the two cannot drift apart:
#   - the section's scene, shown indented, must equal SCENE (the file in
#     docs/examples/first_scene/) byte for byte, apart from the indent;
#   - its command lines (indented, starting `build/renderer/xval `) must be
#     the three it describes, render, crosscheck and validate, in that order;
#   - each runs, exactly as written, from a fresh folder WORK holding what a
#     checkout holds at those paths: build/renderer/xval (XVAL), docs/ and
#     reference/ (links to the checkout's), and exits 0;
#   - what they write is there, crosscheck's metrics.json says pass, and
#     validate's results.json has one case that passes with every pair
#     compared and passing and its Blender-import check passing.
# -DXVAL=... -DREADME=... -DSCENE=... -DCHECKOUT=... -DWORK=...
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(first_scene.cmake XVAL README SCENE CHECKOUT WORK)

file(READ ${README} readme)
string(FIND "${readme}" "\n## Your first scene\n" begin)
if(begin EQUAL -1)
  message(FATAL_ERROR "${README}: no section \"## Your first scene\"")
endif()
string(SUBSTRING "${readme}" ${begin} -1 section)
string(SUBSTRING "${section}" 1 -1 section)
string(FIND "${section}" "\n## " end)
string(SUBSTRING "${section}" 0 ${end} section)

# The section's indented lines: the scene (up to the first blank line after
# its opening brace) and the commands.
# (CMake does not split a list at a ";" inside unbalanced brackets: [ and ]
# are stood in for while the lines are a list.)
string(REPLACE ";" "\\;" section "${section}")
string(REPLACE "[" "<lb>" section "${section}")
string(REPLACE "]" "<rb>" section "${section}")
string(REPLACE "\n" ";" lines "${section}")
set(shown "")
set(in_scene FALSE)
set(commands "")
foreach(line IN LISTS lines)
  string(REPLACE "<lb>" "[" line "${line}")
  string(REPLACE "<rb>" "]" line "${line}")
  if(line MATCHES "^    build/renderer/xval ")
    string(SUBSTRING "${line}" 4 -1 cmd)
    list(APPEND commands "${cmd}")
  elseif(line STREQUAL "    {")
    set(in_scene TRUE)
  endif()
  if(in_scene)
    if(line STREQUAL "")
      set(in_scene FALSE)
    else()
      string(SUBSTRING "${line}" 4 -1 line)  # the indent (REGEX REPLACE "^    " would strip every 4 spaces)
      string(APPEND shown "${line}\n")
    endif()
  endif()
endforeach()
file(READ ${SCENE} scene_text)
expect_eq("the scene shown in README.md's \"Your first scene\" against ${SCENE}" "${shown}" "${scene_text}")

list(LENGTH commands n)
expect_eq("command lines in README.md's \"Your first scene\"" "${n}" "3")
set(k 0)
foreach(sub render crosscheck validate)
  list(GET commands ${k} cmd)
  if(NOT cmd MATCHES "^build/renderer/xval ${sub} ")
    message(FATAL_ERROR "README.md's \"Your first scene\", command ${k}: \"${cmd}\", expected xval ${sub}")
  endif()
  math(EXPR k "${k} + 1")
endforeach()

# A fresh folder with the checkout's paths.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/build/renderer)
file(CREATE_LINK ${XVAL} ${WORK}/build/renderer/xval SYMBOLIC)
file(CREATE_LINK ${CHECKOUT}/docs ${WORK}/docs SYMBOLIC)
file(CREATE_LINK ${CHECKOUT}/reference ${WORK}/reference SYMBOLIC)

foreach(cmd IN LISTS commands)
  separate_arguments(argv UNIX_COMMAND "${cmd}")
  message("in ${WORK}: ${cmd}")
  execute_process(COMMAND ${argv} WORKING_DIRECTORY ${WORK} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 600)
  message("exit: ${rc}\n${out}${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "README.md's \"${cmd}\": exit ${rc}, expected 0")
  endif()
endforeach()

# What the section says they write.
foreach(f first/first_scene.png first/crosscheck/metrics.json first/validation/results.json
          first/validation/report.html)
  if(NOT EXISTS ${WORK}/${f})
    message(FATAL_ERROR "${WORK}/${f}: not written")
  endif()
endforeach()
file(READ ${WORK}/first/crosscheck/metrics.json metrics)
get_json(pass "${metrics}" pass)
expect_eq("crosscheck metrics.json pass" "${pass}" "ON")
file(READ ${WORK}/first/validation/results.json results)
string(JSON ncases LENGTH "${results}" cases)
expect_eq("validate: cases" "${ncases}" "1")
get_json(pass "${results}" cases 0 pass)
expect_eq("validate: cases[0].pass" "${pass}" "ON")
get_json(renderers "${results}" renderers)
string(JSON nrenderers LENGTH "${results}" renderers)
string(JSON npairs LENGTH "${results}" cases 0 pairs)
# Every pair of the image renderers (all but the geometry check) compared.
math(EXPR want_pairs "(${nrenderers} - 1) * (${nrenderers} - 2) / 2")
expect_eq("validate: pairs compared (renderers ${renderers})" "${npairs}" "${want_pairs}")
math(EXPR last "${npairs} - 1")
foreach(p RANGE ${last})
  get_json(name "${results}" cases 0 pairs ${p} pair)
  get_json(pass "${results}" cases 0 pairs ${p} pass)
  expect_eq("validate: pair ${name} pass" "${pass}" "ON")
endforeach()
get_json(verdict "${results}" cases 0 geometry_checks 0 verdict)
expect_eq("validate: the Blender-import check" "${verdict}" "pass")
