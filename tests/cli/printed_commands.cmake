# Every command xval validate and xval golden print for a run with a
# renderer defined by a file (docs/renderer-file.md) runs as printed: the
# next steps on stderr ("look closer: xval crosscheck ...", the golden
# update step), the report's "Reproduce:" line and golden check's
# "accept the fresh render" command are each run, and each must exit 0 or 1
# (its verdict), never 2 (a usage error, "unknown renderer").
# The golden update step is printed only for the renderer to blame, and only
# when its golden set holds the scene. The user's renderer stores and checks
# its own golden set (golden-NAME) and validate compares with it.
# Paths hold spaces, so the printed commands must quote them.
# Arguments: XVAL, SCENE, STANDIN (tests/cli/standin_renderer.sh), WORK.
foreach(_v XVAL SCENE STANDIN WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "printed_commands.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
set(_set "${WORK}/my set")
set(_defdir "${WORK}/my def")
file(MAKE_DIRECTORY "${_set}/scenes" "${_defdir}" ${WORK}/tol ${WORK}/elsewhere)
file(COPY_FILE ${SCENE} "${_set}/scenes/tiny.json")
file(COPY ${STANDIN} DESTINATION "${_defdir}")
set(_def "${_defdir}/standin.json")
# The tolerance file given: one the rule would not find for the scene.
file(READ ${CMAKE_CURRENT_LIST_DIR}/../../reference/tolerances.json _tol)
file(WRITE ${WORK}/tol/tolerances.json "${_tol}")
function(define_standin mode)
  file(WRITE "${_def}" "{\"format\": \"xval-renderer/1\",
 \"name\": \"standin\",
 \"input\": \"scene\",
 \"command\": [\"./standin_renderer.sh\", \"${mode}\", \"{scene}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./standin_renderer.sh\", \"--version\"]}\n")
endfunction()

set(XVAL_RUN_DIR ${WORK}/elsewhere)
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

# Runs each `xval ...` command of LINES (one a line, as printed) from
# another folder; each must exit 0 or 1. COUNT_VAR gets how many ran.
function(run_printed lines what count_var)
  set(_n 0)
  foreach(_line IN LISTS lines)
    string(REGEX REPLACE "^xval " "" _args "${_line}")
    separate_arguments(_argv UNIX_COMMAND "${_args}")
    execute_process(COMMAND ${CMAKE_COMMAND} -E env XVAL=${XVAL} ${XVAL} ${_argv}
                    WORKING_DIRECTORY ${WORK} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err
                    TIMEOUT 120)
    if(NOT _rc EQUAL 0 AND NOT _rc EQUAL 1)
      message(FATAL_ERROR "${what}: the printed command\n  ${_line}\nexits ${_rc} (expected its verdict, 0 or 1):\n${_out}\n${_err}")
    endif()
    math(EXPR _n "${_n} + 1")
  endforeach()
  set(${count_var} ${_n} PARENT_SCOPE)
endfunction()

# The commands printed on stderr ("  look closer: xval ...", "  xval golden
# update ...") and on the report's Reproduce lines.
function(printed_commands text report out_var)
  set(_cmds)
  string(REGEX MATCHALL "look closer: xval [^\n]*" _m "${text}")
  foreach(_c IN LISTS _m)
    string(REGEX REPLACE "^look closer: " "" _c "${_c}")
    list(APPEND _cmds "${_c}")
  endforeach()
  string(REGEX MATCHALL "\n  xval golden update [^\n]*" _m "${text}")
  foreach(_c IN LISTS _m)
    string(STRIP "${_c}" _c)
    list(APPEND _cmds "${_c}")
  endforeach()
  file(READ ${report} _html)
  # HTML's escapes undone first (&#39; holds a ';', CMake's list separator).
  string(REPLACE "&#39;" "'" _html "${_html}")
  string(REPLACE "&quot;" "\"" _html "${_html}")
  string(REGEX MATCHALL "Reproduce: <code>[^<]*</code>" _m "${_html}")
  if(NOT _m)
    message(FATAL_ERROR "${report}: no Reproduce line")
  endif()
  foreach(_c IN LISTS _m)
    string(REGEX REPLACE "^Reproduce: <code>(.*)</code>$" "\\1" _c "${_c}")
    string(REPLACE "&lt;" "<" _c "${_c}")
    string(REPLACE "&gt;" ">" _c "${_c}")
    string(REPLACE "&amp;" "&" _c "${_c}")
    list(APPEND _cmds "${_c}")
  endforeach()
  set(${out_var} "${_cmds}" PARENT_SCOPE)
endfunction()

# 1. The reference's golden set exists; the user's renderer disagrees and
#    the majority (reference and its golden images) blames it: no golden
#    update step (neither for the reference, not to blame, nor for standin,
#    which has no golden set yet).
run_xval(0 _o golden update "${_set}/scenes")
define_standin(dim)
run_xval(1 _o validate "${_set}/scenes" --renderers reference,golden,standin --renderer-file "${_def}"
         --tolerances ${WORK}/tol/tolerances.json -o ${WORK}/out1)
expect("${_o}" "FAIL tiny \\(standin deviates" "the standin is to blame")
# Each failing pair says which criteria it fails, with their numbers.
expect("${_o}" "\n  reference-standin fails: unexplained error [0-9.]+/65535 > cap 128/65535 at \\([0-9]+, [0-9]+\\)"
       "the failing pair's criteria")
if(_o MATCHES "golden update")
  message(FATAL_ERROR "a golden update step was printed although the reference is not to blame:\n${_o}")
endif()
printed_commands("${_o}" ${WORK}/out1/report.html _cmds)
foreach(_c IN LISTS _cmds)
  expect("${_c}" "--renderer-file '${_def}'.*--tolerances ${WORK}/tol/tolerances.json" "a printed command's options")
endforeach()
expect("${_cmds}" "xval validate '${_set}/scenes/tiny.json' -o ${WORK}/out1/tiny.validate --renderers reference,golden,standin"
       "the Reproduce line")
run_printed("${_cmds}" "run 1" _n)
if(NOT _n EQUAL 3)  # crosscheck golden, crosscheck standin, reproduce
  message(FATAL_ERROR "run 1: ${_n} printed commands, expected 3:\n${_cmds}")
endif()

# 2. The user's renderer stores its own golden set (golden/standin) and
#    checks it.
define_standin(pass)
run_xval(0 _o golden update "${_set}/scenes" --renderer standin --renderer-file "${_def}")
if(NOT EXISTS "${_set}/golden/standin/manifest.json" OR NOT EXISTS "${_set}/golden/standin/tiny.exr")
  message(FATAL_ERROR "golden update --renderer standin stored no golden/standin set:\n${_o}")
endif()
run_xval(0 _o golden check "${_set}/scenes" --renderer standin --renderer-file "${_def}")
expect("${_o}" "1 of 1 scenes match their golden images of standin" "golden check --renderer standin")

# 3. Its images change: golden check prints the accepting command, and
#    validate, where the majority (reference and standin's golden images)
#    blames standin, prints the golden update step for standin.
define_standin(dim)
run_xval(1 _o golden check "${_set}/scenes" --renderer standin --renderer-file "${_def}")
string(REGEX MATCH "accept the fresh render: (xval [^\n]*)" _m "${_o}")
if(NOT _m)
  message(FATAL_ERROR "golden check printed no accepting command:\n${_o}")
endif()
set(_accept "${CMAKE_MATCH_1}")
expect("${_accept}" "--renderer standin --renderer-file '${_def}'" "the accepting command")
run_xval(1 _o validate "${_set}/scenes" --renderers reference,standin,golden-standin --renderer-file "${_def}"
         -o ${WORK}/out2)
expect("${_o}" "FAIL tiny \\(standin deviates.*after an intended change of standin, store its images anew:\n  xval golden update '${_set}/scenes/tiny.json' --renderer standin --renderer-file '${_def}'"
       "the golden update step for standin")
if(_o MATCHES "--renderer reference")
  message(FATAL_ERROR "a golden update step for the reference, which is not to blame:\n${_o}")
endif()
printed_commands("${_o}" ${WORK}/out2/report.html _cmds)
list(APPEND _cmds "${_accept}")
run_printed("${_cmds}" "run 2" _n)
if(NOT _n EQUAL 5)  # crosscheck standin, crosscheck golden-standin, golden update, reproduce, accept
  message(FATAL_ERROR "run 2: ${_n} printed commands, expected 5:\n${_cmds}")
endif()
# The golden update step ran: standin's golden images are its new ones.
run_xval(0 _o golden check "${_set}/scenes" --renderer standin --renderer-file "${_def}")
run_xval(0 _o validate "${_set}/scenes" --renderers standin,golden-standin --renderer-file "${_def}" -o ${WORK}/out3)
