# Without an EGL driver the gl renderer is unavailable, with EGL's reason,
# and a render or crosscheck with it is an error, never a pass or an
# image. The EGL dispatcher (libglvnd) is pointed at a vendor file that
# does not exist (__EGL_VENDOR_LIBRARY_FILENAMES), so no EGL display can be
# made. With the dispatcher left alone, gl is available (this machine has
# Mesa), so the variable is what the test changes.
# Arguments: XVAL, SCENE (a small scene file), TOLERANCES, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(gl_unavailable.cmake XVAL SCENE TOLERANCES WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
set(no_egl "__EGL_VENDOR_LIBRARY_FILENAMES=${WORK}/no_such_vendor.json")

# The field FIELD of renderer gl in `xval renderers --json` run with ENV.
function(gl_field env field result)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env ${env} ${XVAL} renderers --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE err TIMEOUT 120)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "xval renderers --json (env ${env}) exited ${rc}: ${err}")
  endif()
  string(JSON n LENGTH "${json}" renderers)
  math(EXPR last "${n} - 1")
  foreach(k RANGE ${last})
    string(JSON _id GET "${json}" renderers ${k} id)
    if(_id STREQUAL "gl")
      string(JSON _v GET "${json}" renderers ${k} ${field})
      set(${result} "${_v}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "xval renderers --json does not list gl")
endfunction()

gl_field("XVAL_UNUSED=1" available _a)
if(NOT _a)
  gl_field("XVAL_UNUSED=1" reason _why)
  message(FATAL_ERROR "gl is unavailable on this machine (${_why}): the test needs an EGL driver to remove")
endif()
gl_field("${no_egl}" available _a)
gl_field("${no_egl}" reason _why)
message("gl without an EGL vendor: available ${_a}, reason: ${_why}")
if(_a)
  message(FATAL_ERROR "gl is listed as available without an EGL vendor library")
endif()
expect_in("${_why}" "EGL")

# A render with it fails (exit 2, an error, as for any renderer that cannot run),
# says why, and leaves no image.
run(2 ${CMAKE_COMMAND} -E env ${no_egl} ${XVAL} render ${SCENE} --renderer gl -o ${WORK}/gl.exr)
expect_in("${err}" "EGL")
if(EXISTS ${WORK}/gl.exr)
  message(FATAL_ERROR "a gl render without EGL wrote ${WORK}/gl.exr")
endif()
# A crosscheck with it is an error (exit 2), not a pass or a failure.
run(2 ${CMAKE_COMMAND} -E env ${no_egl} ${XVAL} crosscheck ${SCENE} --renderer gl
    --tolerances ${TOLERANCES} -o ${WORK}/cc)
expect_in("${err}" "EGL")
