# A pair that fails only on the fraction within tolerance (issue #36),
# end to end through `xval validate`: three renderers, the reference and
# two users' renderers by file (tests/cli/standin_renderer.sh: `alpha`
# hands the scene to the reference renderer, `kilo` halves its image).
#   - With a cap on unexplained error above kilo's errors, kilo's pairs fail
#     on the fraction alone: results.json lists that one criterion, the
#     console and the report's cell name it, and the attribution says kilo
#     deviates only on the fraction (the compare step's soft verdict);
#   - with the default cap (128/65535) they fail on the cap too, listed
#     first, and kilo simply deviates.
# Arguments: XVAL, SCENE, STANDIN, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(fraction_only.cmake XVAL SCENE STANDIN WORK)
get_filename_component(XVAL ${XVAL} ABSOLUTE)  # the stand-in runs it from its work folder
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)
write_standin_renderer(${WORK}/def alpha pass)
write_standin_renderer(${WORK}/def kilo dim)
# The default tolerance but for the cap: the whole scale.
file(WRITE ${WORK}/wide_cap.json "{\"description\": \"the default, with no cap on unexplained error\",
 \"default\": {\"max_abs_16bit\": 2, \"fraction\": 0.999, \"max_unexplained_16bit\": 65535}}\n")

function(validate out)
  run(1 ${CMAKE_COMMAND} -E env XVAL=${XVAL} ${XVAL} validate ${SCENE} -o ${out} --jobs 2 --timeout 60
      --renderers reference,alpha,kilo --renderer-file ${WORK}/def/alpha.json --renderer-file ${WORK}/def/kilo.json
      ${ARGN})
  set(err "${err}" PARENT_SCOPE)
endfunction()

# 1. The fraction alone.
validate(${WORK}/soft --tolerances ${WORK}/wide_cap.json)
expect_in("${err}" "FAIL tiny (kilo deviates, only on the fraction within tolerance (reference and alpha agree))")
if(NOT err MATCHES "\n  reference-kilo fails: fraction within tolerance [0-9.]+% < 99\\.9% \\([0-9]+ of [0-9]+ pixels outside\\)\n")
  message(FATAL_ERROR "the console does not name the fraction as reference-kilo's only failing criterion")
endif()
file(READ ${WORK}/soft/results.json _json)
get_json(_pairs "${_json}" cases 0 pairs)
string(JSON _n LENGTH "${_pairs}")
set(_seen "")
math(EXPR _last "${_n} - 1")
foreach(_i RANGE ${_last})
  get_json(_key "${_pairs}" ${_i} pair)
  get_json(_failed "${_pairs}" ${_i} failed)
  string(JSON _nf LENGTH "${_failed}")
  if(_key STREQUAL "reference-alpha")
    expect_eq("reference-alpha's failed criteria" "${_nf}" "0")
  else()
    expect_eq("${_key}'s failed criteria" "${_nf}" "1")
    get_json(_k "${_failed}" 0 key)
    expect_eq("${_key}'s failed criterion" "${_k}" "fraction")
  endif()
  string(APPEND _seen "${_key} ")
endforeach()
expect_eq("pairs" "${_seen}" "reference-alpha reference-kilo alpha-kilo ")
file(READ ${WORK}/soft/report.html _html)
expect_in("${_html}" "<td title=\"reference-kilo\" class=\"l fail\">FAIL fraction ")

# 2. The default cap: kilo's errors exceed it, the cap is listed first.
validate(${WORK}/hard)
expect_in("${err}" "FAIL tiny (kilo deviates (reference and alpha agree))")
if(NOT err MATCHES "\n  reference-kilo fails: unexplained error [0-9.]+/65535 > cap 128/65535 at \\([0-9]+, [0-9]+\\); fraction within tolerance ")
  message(FATAL_ERROR "the console does not name the cap, then the fraction, as reference-kilo's failing criteria")
endif()
