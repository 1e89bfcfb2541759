# Images read back are checked on their header before any pixel is
# allocated, and only regular files are opened (image/image_header.h):
#   - `xval compare` with an image whose header claims another size, or
#     more than the limit, is refused naming both sizes or the limit;
#   - `xval compare` with a FIFO is refused at once (it blocked forever);
#   - xval's own PNG keeps the hit mask in its alpha: compared with the EXR
#     of the same render it agrees (no mask disagreement, exit 0); an RGB
#     PNG (alpha stripped by oiiotool) gets the has-no-alpha note;
#   - a stand-in povray whose PNG claims 4000x4000 for a 16x16 scene: the
#     render fails saying so (before, 192 MB were allocated first).
# Arguments: XVAL, SCENE (16x16), CLAIMS (a PNG header claiming 4000x4000),
# HUGE (one claiming 100000x100000), WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(image_headers.cmake XVAL SCENE CLAIMS HUGE WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin)

run(0 ${XVAL} render ${SCENE} -o ${WORK}/t.exr -q)
run(0 ${XVAL} render ${SCENE} -o ${WORK}/t.png -q)

run(2 ${XVAL} compare ${WORK}/t.exr ${CLAIMS})
expect_in("${err}" "cannot compare ${WORK}/t.exr (16x16) with ${CLAIMS} (4000x4000)")
run(2 ${XVAL} compare ${HUGE} ${HUGE})
expect_in("${err}" "the image is 100000x100000; the limit is 16384 on a side and 67108864 pixels in all")

execute_process(COMMAND mkfifo ${WORK}/fifo RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "mkfifo failed: ${_rc}")
endif()
run(2 ${XVAL} compare ${WORK}/t.exr ${WORK}/fifo)
expect_in("${err}" "fifo: is not a regular file")

run(0 ${XVAL} compare ${WORK}/t.exr ${WORK}/t.png --json)
expect_in("${out}" "\"mask_disagree\": 0,")
if(err MATCHES "no alpha channel")
  message(FATAL_ERROR "xval's own PNG was taken for one without alpha:\n${err}")
endif()
execute_process(COMMAND oiiotool ${WORK}/t.png --ch R,G,B -o ${WORK}/rgb.png RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "oiiotool --ch R,G,B failed: ${_rc}")
endif()
run(1 ${XVAL} compare ${WORK}/t.exr ${WORK}/rgb.png)
expect_in("${err}" "rgb.png has no alpha channel")

# The stand-in writes where the real POV-Ray would: the Output_File_Name
# of the scene.ini it is given (a fresh name for every attempt).
file(WRITE ${WORK}/bin/povray "#!/bin/sh\nout=$(/bin/sed -n 's/^Output_File_Name=//p' scene.ini)\nfor a in \"$@\"; do o=$(echo \"$a\" | /bin/sed -n 's/^+O//p'); [ -z \"$o\" ] || out=$o; done\ncp '${CLAIMS}' \"$out\"\n")
file(CHMOD ${WORK}/bin/povray PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
execute_process(COMMAND ${CMAKE_COMMAND} -E env PATH=${WORK}/bin:/usr/bin:/bin
                        ${XVAL} render ${SCENE} -o ${WORK}/pov.exr --renderer povray --timeout 20 -q
  RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 60)
message("povray stand-in: exit ${rc}\n${err}")
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "exit status ${rc}, expected 2 (an error)")
endif()
expect_in("${err}" "povray wrote an unusable image")
expect_in("${err}" "the image is 4000x4000; expected 16x16")
