# Helpers shared by CLI test scripts (include() after XVAL is set):
#   run_xval(EXPECT_RC OUT_VAR ARGS...)  runs `${XVAL} ARGS...` with XVAL in
#     its environment (stand-in renderers call it back), in
#     ${XVAL_RUN_DIR} when set, killed after ${XVAL_RUN_TIMEOUT} seconds
#     (default 120); fails the test unless it exits EXPECT_RC; OUT_VAR gets
#     stdout followed by stderr.
#   expect(TEXT REGEX WHAT)  fails the test unless TEXT matches REGEX.
if(NOT DEFINED XVAL_RUN_TIMEOUT)
  set(XVAL_RUN_TIMEOUT 120)
endif()
function(run_xval expect_rc out_var)
  set(_dir)
  if(DEFINED XVAL_RUN_DIR)
    set(_dir WORKING_DIRECTORY ${XVAL_RUN_DIR})
  endif()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env XVAL=${XVAL} ${XVAL} ${ARGN}
                  RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err
                  ${_dir} TIMEOUT ${XVAL_RUN_TIMEOUT})
  if(NOT _rc EQUAL expect_rc)
    message(FATAL_ERROR "xval ${ARGN}: exit ${_rc}, expected ${expect_rc}\n${_out}\n${_err}")
  endif()
  set(${out_var} "${_out}${_err}" PARENT_SCOPE)
endfunction()
function(expect text regex what)
  if(NOT text MATCHES "${regex}")
    message(FATAL_ERROR "${what}: expected \"${regex}\" in:\n${text}")
  endif()
endfunction()
