# xval pack (docs/pack.md): a scratch set (a sphere scene, and an OBJ
# scene whose model file names a material file that names a texture, its
# own tolerance file, golden images of the reference renderer) is packed,
# the set is moved away, the archive unpacked into another folder, and from
# a third folder as working directory:
#   - pack --verify passes; validate --renderers golden,reference passes,
#     using the unpacked set's tolerance file and golden images;
#   - a changed, a missing and an added file each fail --verify, named;
#   - changing the OBJ's material file makes validate --resume redo the
#     OBJ scene's jobs (the input hash covers the files a model refers to).
# Refusals (exit 2, no archive written): a scene that is a symbolic link
# to a file outside the set, a texture outside the set, an absolute path,
# a backslash in a packed name, an output name not ending in .tar.gz.
# Arguments: XVAL, TINY (a small scene file), SET_FILES (tests/cli/pack_set),
# TOLERANCES (a tolerance file), WORK.
foreach(_v XVAL TINY SET_FILES TOLERANCES WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "pack.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/myset/scenes ${WORK}/myset/models ${WORK}/unpacked ${WORK}/elsewhere)
file(COPY_FILE ${TINY} ${WORK}/myset/scenes/tiny.json)
file(COPY_FILE ${SET_FILES}/quad.json ${WORK}/myset/scenes/quad.json)
foreach(_f quad.obj quad.mtl quad_texture.png)
  file(COPY_FILE ${SET_FILES}/${_f} ${WORK}/myset/models/${_f})
endforeach()
file(COPY_FILE ${TOLERANCES} ${WORK}/myset/tolerances.json)

set(XVAL_RUN_DIR ${WORK}/elsewhere)
set(XVAL_RUN_TIMEOUT 240)
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

run_xval(0 _o golden update ${WORK}/myset/scenes)
run_xval(0 _o pack ${WORK}/myset -o ${WORK}/myset.tar.gz)
expect("${_o}" "\\[1/9\\] .*scenes/quad.json \\(scene\\)" "pack progress")
expect("${_o}" "models/quad.mtl \\(model\\).*models/quad_texture.png \\(model\\)" "pack: the files the OBJ refers to")
expect("${_o}" "wrote .*myset.tar.gz: 9 files" "pack")
file(GLOB _left ${WORK}/myset.tar.gz.partial*)
if(_left)
  message(FATAL_ERROR "pack left ${_left}")
endif()

# The set is gone from where it was made; the archive is unpacked elsewhere.
file(RENAME ${WORK}/myset ${WORK}/myset.moved)
execute_process(COMMAND tar -xzf ${WORK}/myset.tar.gz WORKING_DIRECTORY ${WORK}/unpacked RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "tar -xzf ${WORK}/myset.tar.gz: exit ${_rc}")
endif()
set(_u ${WORK}/unpacked/myset)
file(READ ${_u}/pack-manifest.json _manifest)
file(SHA256 ${_u}/models/quad.mtl _mtl_hash)
expect("${_manifest}" "\"format\": \"xval-pack/1\".*\"xval_version\": \"xval [0-9.]+\".*\"git_commit\": \".+\".*\"date_utc\": \"20"
       "pack manifest")
expect("${_manifest}" "\"path\": \"models/quad.mtl\",[ \n]*\"role\": \"model\",[ \n]*\"size\": [0-9]+,[ \n]*\"sha256\": \"${_mtl_hash}\""
       "pack manifest entry")
run_xval(0 _o pack --verify ${_u})
expect("${_o}" "every file as packed" "pack --verify")

run_xval(0 _o validate ${_u}/scenes --renderers golden,reference -o ${WORK}/out)
expect("${_o}" "tolerances: ${_u}/tolerances.json \\(nearest to the scene\\)" "validate of the unpacked set: its tolerance file")
file(READ ${WORK}/out/results.json _results)
expect("${_results}" "\"golden-reference\"|\"reference-golden\"" "validate: the golden pair")

# The OBJ's material file changes: its scene's jobs are no longer done.
file(APPEND ${_u}/models/quad.mtl "# changed\n")
run_xval(0 _o validate ${_u}/scenes --renderers golden,reference -o ${WORK}/out --plan-only --resume)
expect("${_o}" "^0\n1\n.*wrote .*4 jobs .*2 to run" "validate --resume after the mtl changed")

# Tampering, each file named. A file of another size is named without
# being read: a 256 GiB sparse file in place of the texture is answered at
# once (killed after 20 s, it would take minutes to hash); one of the same
# size is hashed.
file(READ ${_u}/tolerances.json _tol)
string(REPLACE "fraction" "fractioN" _tol "${_tol}")
file(WRITE ${_u}/tolerances.json "${_tol}")
file(SHA256 ${_u}/models/quad_texture.png _texture_hash)
execute_process(COMMAND truncate -s 256G ${_u}/models/quad_texture.png RESULT_VARIABLE _rc)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "truncate -s 256G ${_u}/models/quad_texture.png: exit ${_rc}")
endif()
set(XVAL_RUN_TIMEOUT 20)
run_xval(1 _o pack --verify ${_u})
set(XVAL_RUN_TIMEOUT 240)
file(REMOVE ${_u}/models/quad_texture.png)
expect("${_o}" "FAIL ${_u}/models/quad.mtl: changed \\([0-9]+ bytes; packed: [0-9]+ bytes, SHA-256 ${_mtl_hash}\\)"
       "pack --verify: a changed file")
expect("${_o}" "FAIL ${_u}/models/quad_texture.png: changed \\(274877906944 bytes; packed: [0-9]+ bytes, SHA-256 ${_texture_hash}\\)"
       "pack --verify: a sparse 256 GiB file, by its size")
expect("${_o}" "FAIL ${_u}/tolerances.json: changed \\([0-9]+ bytes, SHA-256 [0-9a-f]+; packed: [0-9]+ bytes, [0-9a-f]+\\)"
       "pack --verify: a file of the same size, by its hash")
file(REMOVE ${_u}/golden/reference/tiny.exr)
file(WRITE ${_u}/scenes/extra.json "{}")
run_xval(1 _o pack --verify ${_u})
expect("${_o}" "FAIL ${_u}/golden/reference/tiny.exr: missing" "pack --verify: a missing file")
expect("${_o}" "FAIL ${_u}/scenes/extra.json: not in the pack manifest" "pack --verify: an added file")
expect("${_o}" "5 file\\(s\\) not as packed" "pack --verify: the count")

# Refusals: nothing written.
function(refused set regex what)
  run_xval(2 _o pack ${set} -o ${WORK}/refused.tar.gz)
  expect("${_o}" "${regex}" "${what}")
  if(EXISTS ${WORK}/refused.tar.gz)
    message(FATAL_ERROR "${what}: an archive was written")
  endif()
endfunction()
file(MAKE_DIRECTORY ${WORK}/bad/scenes)
file(COPY_FILE ${TINY} ${WORK}/outside.json)
file(CREATE_LINK ${WORK}/outside.json ${WORK}/bad/scenes/linked.json SYMBOLIC)
refused(${WORK}/bad "scenes/linked.json is a symbolic link .* resolving to .*outside.json, outside the set folder" "a link out of the set")
file(REMOVE ${WORK}/bad/scenes/linked.json)
file(READ ${SET_FILES}/quad.json _quad)
string(REPLACE "../models/quad.obj" "../../myset.moved/models/quad.obj" _outside "${_quad}")
file(WRITE ${WORK}/bad/scenes/quad.json "${_outside}")
refused(${WORK}/bad "scenes/quad.json: objects\\[0\\].path: .*myset.moved/models/quad.obj is outside the set folder .*bad; xval pack packs only files inside the set"
        "a model file outside the set")
string(REPLACE "../models/quad.obj" "${WORK}/myset.moved/models/quad.obj" _absolute "${_quad}")
file(WRITE ${WORK}/bad/scenes/quad.json "${_absolute}")
refused(${WORK}/bad "scenes/quad.json: objects\\[0\\].path: \"[^\"]*\" is an absolute path" "an absolute reference")
file(COPY_FILE ${SET_FILES}/quad_texture.png "${WORK}/bad/scenes/a\\b.png")
file(WRITE ${WORK}/bad/scenes/quad.json "{\"format\": \"xval-scene/1\", \"name\": \"textured\",
 \"camera\": {\"position\": [0, 0, 4], \"target\": [0, 0, 0], \"width\": 16, \"height\": 16},
 \"objects\": [{\"shape\": \"sphere\"}],
 \"material\": {\"model\": {\"type\": \"lambert\"}, \"texture\": {\"source\": \"image\", \"path\": \"a\\\\b.png\", \"filter\": \"nearest\"}},
 \"lights\": [{\"type\": \"directional\", \"direction\": [-0.3, -0.4, -1]}]}\n")
refused(${WORK}/bad "scenes/quad.json: material.texture.path: .*a.b.png: cannot be packed: a backslash in the path" "a backslash in a name")
run_xval(2 _o pack ${WORK}/myset.moved -o ${WORK}/set.zip)
expect("${_o}" "set.zip: expected a file name ending in .tar.gz" "pack -o set.zip")
