# `xval validate` runs the Blender-import check as a case's geometry check
# (renderer/validate/results/geometry_checks.h), recorded in results.json
# (cases[].geometry_checks), report.html and the JUnit file:
#   MODE pass      a scene of model files (mesh_wuson_ply) with renderers
#                  reference,blender-import: exit 0, a passing check with
#                  its metrics and bounds, the case passes; the report's
#                  summary counts it and its case shows the check's table;
#                  JUnit has it as a passing testcase; --plan-only --resume
#                  finds nothing to redo, --compare-only gives the same
#                  verdict; validating SECOND into the same folder keeps
#                  the case, its check compared again.
#   MODE builtin   a scene with built-in shapes beside its model files
#                  (mesh_objects_transformed_untextured) with renderers
#                  reference,povray,blender-import: exit 0, the check not
#                  expressible with Blender's reason (a built-in shape), the
#                  case decided on reference-povray, which passes.
# -DXVAL=... -DSCENE=... -DRENDERERS=a,b,... -DTOLERANCES=... -DOUT=... -DMODE=pass|builtin
# [-DSECOND=... (MODE pass: another scene of model files)]
include(${CMAKE_CURRENT_LIST_DIR}/../cli/cli_run.cmake)
require_defined(blender_import_validate.cmake XVAL SCENE RENDERERS TOLERANCES OUT MODE)
file(REMOVE_RECURSE ${OUT})
# As run() (cli_run.cmake), with the time a Blender import and POV-Ray take.
execute_process(COMMAND ${XVAL} validate ${SCENE} --renderers ${RENDERERS} --tolerances ${TOLERANCES} -o ${OUT}
                        --junit ${OUT}/junit.xml
                RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 800)
message("xval validate: exit ${rc}\n${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "xval validate exited ${rc}, expected 0")
endif()
file(READ ${OUT}/results.json results)
# A member of results.json (cli_run.cmake's get_json on its text).
function(get var)
  get_json(_v "${results}" ${ARGN})
  set(${var} "${_v}" PARENT_SCOPE)
endfunction()
get(_renderer cases 0 geometry_checks 0 renderer)
get(_against cases 0 geometry_checks 0 against)
get(_verdict cases 0 geometry_checks 0 verdict)
get(_pass cases 0 pass)
expect_eq("the check's renderer" "${_renderer}" "blender-import")
expect_eq("the check's reference" "${_against}" "reference")
expect_eq("the case's verdict" "${_pass}" "ON")
file(READ ${OUT}/report.html html)
file(READ ${OUT}/junit.xml junit)
expect_in("${html}" "<th>reference-blender-import (geometry)<br>verdict</th>")
expect_in("${junit}" "name=\"reference-blender-import (geometry)\"")

if(MODE STREQUAL "pass")
  expect_eq("the check's verdict" "${_verdict}" "pass")
  get(_covered cases 0 geometry_checks 0 metrics covered)
  get(_uv cases 0 geometry_checks 0 metrics uv_compared)
  get(_off cases 0 geometry_checks 0 metrics mask_disagree)
  get(_max_uv cases 0 geometry_checks 0 metrics max_uv)
  get(_bound_uv cases 0 geometry_checks 0 bounds max_uv)
  if(_covered LESS 10000 OR _uv LESS 10000)
    message(FATAL_ERROR "the check compared too little: covered ${_covered}, uv pixels ${_uv}")
  endif()
  string(JSON _n LENGTH "${results}" cases 0 pairs)
  expect_eq("image pairs of reference,blender-import" "${_n}" "0")
  get(_who cases 0 attribution)
  expect_eq("attribution" "${_who}" "no image pair to compare")
  expect_in("${html}" "Geometry checks (reference-blender-import (geometry); docs/model-files.md, \"The Blender-import check\"): <span class=\"pass\">1 pass</span>")
  expect_in("${html}" "<td class=\"l\">reference-blender-import (geometry)</td><td class=\"l pass\">PASS</td><td>${_covered}</td>")
  expect_in("${html}" "<span class=\"pass\">1 pass</span>, <span class=\"fail\">0 fail</span>")
  expect_in("${junit}" "tests=\"1\" failures=\"0\" errors=\"0\" skipped=\"0\"")
  # The job set is done: nothing to redo; the compare step alone agrees.
  run(0 ${XVAL} validate ${SCENE} --renderers ${RENDERERS} --tolerances ${TOLERANCES} -o ${OUT} --plan-only --resume)
  if(NOT "${out}" STREQUAL "")
    message(FATAL_ERROR "--resume would redo jobs ${out}")
  endif()
  run(0 ${XVAL} validate --plan ${OUT}/jobs.json --compare-only)
  file(READ ${OUT}/results.json results)
  get(_again cases 0 geometry_checks 0 metrics max_uv)
  expect_eq("max uv after --compare-only" "${_again}" "${_max_uv}")
  # Another scene into the same folder: the earlier case is kept (its
  # check compared again from its job's passes, not rendered), the new one
  # checked too.
  execute_process(COMMAND ${XVAL} validate ${SECOND} --renderers ${RENDERERS} --tolerances ${TOLERANCES} -o ${OUT}
                  RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 800)
  message("xval validate ${SECOND}: exit ${rc}\n${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "xval validate of a second scene into the folder exited ${rc}, expected 0")
  endif()
  expect_in("${err}" "keeping 1 earlier cases")
  file(READ ${OUT}/results.json results)
  string(JSON _n LENGTH "${results}" cases)
  expect_eq("cases after the second scene" "${_n}" "2")
  foreach(_k 0 1)
    get(_v cases ${_k} geometry_checks 0 verdict)
    expect_eq("case ${_k}'s check" "${_v}" "pass")
  endforeach()
  get(_kept cases 1 geometry_checks 0 metrics max_uv)
  expect_eq("the kept case's max uv" "${_kept}" "${_max_uv}")
  # The check's picture of its passes shows the shape even of a model
  # without uvs (SECOND: an STL, whose UV pass is constant; the uv colours
  # alone were all black), and the report says it is passes, not a render.
  get_filename_component(_second ${SECOND} NAME_WE)
  find_program(_oiiotool oiiotool REQUIRED)
  execute_process(COMMAND ${_oiiotool} --stats ${OUT}/${_second}/blender-import.png
                  OUTPUT_VARIABLE _stats RESULT_VARIABLE _rc)
  string(REGEX MATCH "Stats Max: [0-9]+ [0-9]+ ([0-9]+)" _max "${_stats}")
  if(NOT _rc EQUAL 0 OR NOT _max OR CMAKE_MATCH_1 LESS 64)
    message(FATAL_ERROR "${OUT}/${_second}/blender-import.png: no visible shape (blue max ${CMAKE_MATCH_1}):\n${_stats}")
  endif()
  file(READ ${OUT}/report.html html)
  expect_in("${html}" "blender-import, ")
  expect_in("${html}" "not a render: its geometry passes (red = u, green = v")
elseif(MODE STREQUAL "builtin")
  expect_eq("the check's verdict" "${_verdict}" "not_expressible")
  get(_why cases 0 geometry_checks 0 reason)
  expect_in("${_why}" "a built-in shape, not a model file")
  string(JSON _m ERROR_VARIABLE _no GET "${results}" cases 0 geometry_checks 0 metrics)
  if(NOT _no)
    message(FATAL_ERROR "a not-expressible check has metrics: ${_m}")
  endif()
  get(_p0 cases 0 pairs 0 pair)
  get(_pass0 cases 0 pairs 0 pass)
  expect_eq("the image pair" "${_p0}" "reference-povray")
  expect_eq("reference-povray passes" "${_pass0}" "ON")
  # The check is no image renderer: one pair, two renderers agreeing.
  string(JSON _n LENGTH "${results}" cases 0 pairs)
  expect_eq("image pairs of reference,povray,blender-import" "${_n}" "1")
  get(_who cases 0 attribution)
  expect_eq("attribution" "${_who}" "both agree")
  expect_in("${html}" "<td class=\"nexp\" colspan=\"8\">not expressible: ")
  expect_in("${junit}" "tests=\"2\" failures=\"0\" errors=\"0\" skipped=\"1\"")
else()
  message(FATAL_ERROR "MODE ${MODE}: expected pass or builtin")
endif()
