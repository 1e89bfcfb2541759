# A metric of the table as a declared tolerance criterion
# (docs/scene-format.md, "tolerances": metric criteria), end to end through
# `xval validate`: the scene's set declares, in its tolerances.json beside
# the scene folder (found by the rule of validate/tolerances.h), a per-pixel
# bound of 4096/65535 and a mean FLIP of at most FLIP_MAX, for two users'
# renderers (tests/cli/standin_renderer.sh). (In the set's file, not the
# scene's `tolerances`: the stand-in renders the scene file it is handed
# with `xval render`, which knows no users' renderers to check a scene's
# declaration for them against.)
#   - `alpha` (the reference renderer's image) passes;
#   - `lima` (that image 5% darker: a small exposure fault, every pixel
#     within the per-pixel bound) fails on the FLIP criterion alone, named
#     with its value in the console, results.json (failed, and the
#     tolerance's metrics), the report's cell and JUnit;
#   - without the FLIP criterion the same fault passes: the criterion is
#     what catches it.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(metric_criterion.cmake XVAL SCENE STANDIN WORK)
get_filename_component(XVAL ${XVAL} ABSOLUTE)  # the stand-in runs it from its work folder
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def ${WORK}/set/scenes)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)
write_standin_renderer(${WORK}/def alpha pass)
write_standin_renderer(${WORK}/def lima dim5)
set(FLIP_MAX 0.05)

# The set: tiny.json, and the tolerance file (`metrics`: the criteria).
file(COPY ${SCENE} DESTINATION ${WORK}/set/scenes)
function(write_tolerances metrics)
  file(WRITE ${WORK}/set/tolerances.json "{\"description\": \"the stand-ins' exposure may drift by 1/16 per pixel; what a viewer sees is bounded apart\",
 \"default\": {\"max_abs_16bit\": 4096, \"fraction\": 0.999, \"max_unexplained_16bit\": 4096 ${metrics}}}\n")
endfunction()
write_tolerances(", \"metrics\": {\"flip\": {\"max\": ${FLIP_MAX}}}")

# The recorded bound, as CMake prints a double (0.050000000000000003).
function(expect_bound who got)
  if(NOT got MATCHES "^0\\.050*[0-9]?$")
    message(FATAL_ERROR "${who}'s recorded FLIP bound: \"${got}\", expected ${FLIP_MAX}")
  endif()
endfunction()

function(validate expect_rc scene out)
  run(${expect_rc} ${CMAKE_COMMAND} -E env XVAL=${XVAL} ${XVAL} validate ${scene} -o ${out} --jobs 2 --timeout 60
      --renderers reference,alpha,lima --renderer-file ${WORK}/def/alpha.json
      --renderer-file ${WORK}/def/lima.json --junit ${out}/junit.xml)
  set(err "${err}" PARENT_SCOPE)
endfunction()

# 1. The declared FLIP bound: alpha passes, lima fails on it alone.
validate(1 ${WORK}/set/scenes/tiny.json ${WORK}/flip)
if(NOT err MATCHES "\n  reference-lima fails: mean FLIP [0-9.]+ > max ${FLIP_MAX}\n")
  message(FATAL_ERROR "the console does not name the FLIP criterion, with its value, as reference-lima's failure")
endif()
string(FIND "${err}" "reference-alpha fails" _at)
expect_eq("reference-alpha failing" "${_at}" "-1")
file(READ ${WORK}/flip/results.json _json)
get_json(_pairs "${_json}" cases 0 pairs)
string(JSON _n LENGTH "${_pairs}")
math(EXPR _last "${_n} - 1")
set(_seen "")
foreach(_i RANGE ${_last})
  get_json(_key "${_pairs}" ${_i} pair)
  get_json(_failed "${_pairs}" ${_i} failed)
  string(JSON _nf LENGTH "${_failed}")
  if(_key STREQUAL "reference-alpha")
    expect_eq("reference-alpha's failed criteria" "${_nf}" "0")
    get_json(_bound "${_pairs}" ${_i} metrics tolerance metrics flip max)
    expect_bound("reference-alpha" "${_bound}")
  elseif(_key STREQUAL "reference-lima")
    expect_eq("reference-lima's failed criteria" "${_nf}" "1")
    get_json(_k "${_failed}" 0 key)
    expect_eq("reference-lima's failed criterion" "${_k}" "metric:flip")
    get_json(_bound "${_pairs}" ${_i} metrics tolerance metrics flip max)
    expect_bound("reference-lima" "${_bound}")
  else()
    # alpha-lima: two external renderers, no metric criterion derived; the
    # reason says so.
    string(JSON _has ERROR_VARIABLE _none GET "${_pairs}" ${_i} metrics tolerance metrics)
    if(NOT _has MATCHES "NOTFOUND$")
      message(FATAL_ERROR "alpha-lima has derived metric criteria: ${_has}")
    endif()
    get_json(_reason "${_pairs}" ${_i} metrics tolerance_reason)
    expect_in("${_reason}" "are not derived for this pair")
  endif()
  string(APPEND _seen "${_key} ")
endforeach()
expect_eq("pairs" "${_seen}" "reference-alpha reference-lima alpha-lima ")
file(READ ${WORK}/flip/report.html _html)
expect_in("${_html}" "<td title=\"reference-lima\" class=\"l fail\">FAIL flip ")
expect_in("${_html}" "on 99.9%, flip max ${FLIP_MAX}</td>")
file(READ ${WORK}/flip/junit.xml _junit)
expect_in("${_junit}" "outside the tolerance: mean FLIP ")

# 2. The same fault without the FLIP criterion: within the pixel criteria.
write_tolerances("")
validate(0 ${WORK}/set/scenes/tiny.json ${WORK}/pixels)
