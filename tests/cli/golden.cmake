# Golden images (docs/golden-images.md) of a scene set in a scratch folder:
# update stores them, check passes, the golden renderer reads them; a
# changed scene file is refused (render, crosscheck and check) with the
# accepting command printed, and running that command makes check pass
# again; a stored image whose pixels differ fails check by the tolerance;
# a stored image changed behind the manifest's back is refused.
# Arguments: XVAL, SCENE (a small scene file), WORK.
foreach(_v XVAL SCENE WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "golden.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/set/scenes)
set(_scene ${WORK}/set/scenes/tiny.json)
file(COPY_FILE ${SCENE} ${_scene})
set(_golden ${WORK}/set/golden/reference)

include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

run_xval(0 _o golden update ${WORK}/set/scenes)
foreach(_f ${_golden}/tiny.exr ${_golden}/manifest.json)
  if(NOT EXISTS ${_f})
    message(FATAL_ERROR "golden update: ${_f} not written")
  endif()
endforeach()
file(READ ${_golden}/manifest.json _manifest)
file(SHA256 ${_scene} _scene_hash)
expect("${_manifest}" "\"scene_sha256\": \"${_scene_hash}\"" "manifest")
expect("${_manifest}" "\"scene_file\": \"../../scenes/tiny.json\".*\"settings_sha256\": \"[0-9a-f]+\".*\"renderer_version\": \"xval [0-9.]+\".*\"git_commit\": \".+\".*\"date_utc\": \"20" "manifest")

run_xval(0 _o golden check ${WORK}/set/scenes)
expect("${_o}" "pass .*tiny.json \\(double\\).*1 of 1 scenes match" "golden check")
# A file of another xval format beside the scenes is skipped and said, as
# validate skips it (one rule: scene_file/scene_set.h), not loaded as a scene.
file(WRITE ${WORK}/set/scenes/spec.json "{\"format\": \"xval-generate/1\"}")
run_xval(0 _o golden check ${WORK}/set/scenes)
expect("${_o}" "xval golden: skipping [^\n]*spec.json: a file of format \"xval-generate/1\", not a scene" "golden check of a folder with a spec")
expect("${_o}" "1 of 1 scenes match" "golden check of a folder with a spec")
file(REMOVE ${WORK}/set/scenes/spec.json)
run_xval(0 _o render ${_scene} --renderer golden -o ${WORK}/from_golden.exr -q)
run_xval(0 _o crosscheck ${_scene} --renderer golden -o ${WORK}/cross)
run_xval(0 _o crosscheck ${_scene} --renderer golden:reference -o ${WORK}/cross_alias)

# The scene changes: the stored image no longer shows it.
file(READ ${_scene} _text)
string(REPLACE "\"sphere\"" "\"sphere\", \"radius\": 0.6" _changed "${_text}")
if(_changed STREQUAL _text)
  message(FATAL_ERROR "golden.cmake: could not change ${_scene}")
endif()
file(WRITE ${_scene} "${_changed}")
run_xval(2 _o render ${_scene} --renderer golden -o ${WORK}/stale.exr -q)
expect("${_o}" "the scene file .*tiny.json changed since its golden image was stored \\(SHA-256 [0-9a-f]+, stored for ${_scene_hash}" "render --renderer golden")
if(EXISTS ${WORK}/stale.exr)
  message(FATAL_ERROR "render --renderer golden wrote an image of a changed scene")
endif()
run_xval(2 _o crosscheck ${_scene} --renderer golden -o ${WORK}/cross_stale)
expect("${_o}" "changed since its golden image was stored" "crosscheck --renderer golden")
run_xval(1 _o golden check ${WORK}/set/scenes)
expect("${_o}" "FAIL .*changed since its golden image was stored.*accept the fresh render: xval golden update ([^\n]*)" "golden check")
string(REGEX MATCH "accept the fresh render: xval ([^\n]*)" _m "${_o}")
separate_arguments(_accept UNIX_COMMAND "${CMAKE_MATCH_1}")
run_xval(0 _o ${_accept})
run_xval(0 _o golden check ${WORK}/set/scenes)
expect("${_o}" "1 of 1 scenes match" "golden check after accepting")

# Pixels that differ (another scene's image, the manifest's image hash made
# to match): outside the tolerance.
file(WRITE ${WORK}/other.json "${_text}")
run_xval(0 _o render ${WORK}/other.json -o ${WORK}/other.exr -q)
file(SHA256 ${_golden}/tiny.exr _old)
file(COPY_FILE ${WORK}/other.exr ${_golden}/tiny.exr)
file(SHA256 ${_golden}/tiny.exr _new)
file(READ ${_golden}/manifest.json _manifest)
string(REPLACE "${_old}" "${_new}" _manifest "${_manifest}")
file(WRITE ${_golden}/manifest.json "${_manifest}")
run_xval(1 _o golden check ${WORK}/set/scenes)
expect("${_o}" "FAIL .*outside the tolerance against .*tiny.exr.*accept the fresh render" "golden check of other pixels")

# The stored image changed behind the manifest: refused before comparing.
file(COPY_FILE ${WORK}/from_golden.exr ${_golden}/tiny.exr)
run_xval(1 _o golden check ${WORK}/set/scenes)
expect("${_o}" "the golden image .*tiny.exr changed since it was stored" "golden check of a changed image")
