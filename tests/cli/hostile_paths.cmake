# Hostile folders and files around a run (docs/robustness.md, "What xval
# reads, writes and deletes"), one CASE per test:
#   export_cache   --export-cache DIR holding the user's own folders (one
#                  with a 3 GiB sparse file, over the cache's 2 GiB bound):
#                  after a run that stores entries they are all still there.
#   tolerances     a permissive tolerances.json in a shared folder above the
#                  scenes (mode 1777, the file owned by nobody when run as
#                  root, else writable by others): a scene beside no
#                  `scenes` folder never looks there (the toolkit's own is
#                  used and printed); a set SHARED/scenes finds it and
#                  refuses it (exit 2, its owner or mode named).
#   golden_link    SET/golden/reference a link to a folder outside the set:
#                  golden update refuses it (exit 2) and writes nothing there.
#   bench_scratch  bench with a renderer file: the renderer's work folder is
#                  inside a fresh private folder ($TMPDIR/xval-bench-<id>-
#                  XXXXXX, mode 0700), never at a name known in advance.
#   reserved_names a renderer file named golden-mine (beside one named mine)
#                  or povray is refused, naming the reserved name.
#   golden_duplicate_key  a golden manifest with image_sha256 twice (a wrong
#                  one first) is refused by golden check, naming the field.
#   golden_sparse  a stored image grown to a 256 GiB sparse file: golden
#                  check answers at once (killed after 20 s), not hashing it.
# Arguments: XVAL, SCENE (a small scene file), TOLERANCES (the toolkit's
# tolerance file), WORK, CASE.
foreach(_v XVAL SCENE TOLERANCES WORK CASE)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "hostile_paths.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

function(must_exist)
  foreach(_f ${ARGN})
    if(NOT EXISTS ${_f})
      message(FATAL_ERROR "${CASE}: ${_f} is gone")
    endif()
  endforeach()
endfunction()

function(sh)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE _rc)
  if(NOT _rc EQUAL 0)
    message(FATAL_ERROR "${ARGN}: exit ${_rc}")
  endif()
endfunction()

if(CASE STREQUAL "export_cache")
  file(MAKE_DIRECTORY ${WORK}/cache/photos ${WORK}/cache/notes ${WORK}/cache/.dotted)
  file(WRITE ${WORK}/cache/notes/todo.txt "mine\n")
  file(WRITE ${WORK}/cache/.dotted/keep.txt "mine\n")
  sh(truncate -s 3G ${WORK}/cache/photos/big.jpg)
  run_xval(0 _o validate ${SCENE} --renderers reference,povray -o ${WORK}/out --export-cache ${WORK}/cache
           --tolerances ${TOLERANCES})
  expect("${_o}" "export cache: stored pov" "validate: an entry stored")
  must_exist(${WORK}/cache/photos/big.jpg ${WORK}/cache/notes/todo.txt ${WORK}/cache/.dotted/keep.txt)
  file(GLOB _entries ${WORK}/cache/pov-*)
  if(NOT _entries)
    message(FATAL_ERROR "export_cache: no entry left in ${WORK}/cache")
  endif()
elseif(CASE STREQUAL "tolerances")
  file(MAKE_DIRECTORY ${WORK}/shared/mine ${WORK}/shared/scenes)
  sh(chmod 1777 ${WORK}/shared)
  file(WRITE ${WORK}/shared/tolerances.json
       "{\"default\": {\"max_abs_16bit\": 65535, \"fraction\": 0, \"max_unexplained_16bit\": 65535}}\n")
  execute_process(COMMAND id -u OUTPUT_VARIABLE _uid OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(_uid STREQUAL "0")
    sh(chown nobody ${WORK}/shared/tolerances.json)
    set(_why "owned by uid [0-9]+ \\(nobody\\)")
  else()
    message(STATUS "tolerances: not root, so the planted file is made writable by others instead of owned by nobody")
    sh(chmod 0666 ${WORK}/shared/tolerances.json)
    set(_why "writable by every user \\(mode 0666\\)")
  endif()
  # Run from an empty folder: every path is printed absolute.
  file(MAKE_DIRECTORY ${WORK}/cwd)
  set(XVAL_RUN_DIR ${WORK}/cwd)
  file(COPY_FILE ${SCENE} ${WORK}/shared/mine/tiny.json)
  file(COPY_FILE ${SCENE} ${WORK}/shared/scenes/tiny.json)
  run_xval(0 _o validate ${WORK}/shared/mine/tiny.json -o ${WORK}/out1 --plan-only)
  expect("${_o}" "tolerances: ${TOLERANCES} \\(the toolkit's own\\)" "a scene outside a set: the file above is not looked at")
  run_xval(2 _o validate ${WORK}/shared/scenes -o ${WORK}/out2 --plan-only)
  expect("${_o}" "${WORK}/shared/tolerances.json: the tolerance file nearest to .*tiny.json is not used: it is ${_why}.*--tolerances FILE"
         "a set under a shared folder: the planted file refused")
  # Given on the command line, the user vouches for it: used, and printed.
  run_xval(0 _o validate ${WORK}/shared/scenes -o ${WORK}/out3 --plan-only --tolerances ${WORK}/shared/tolerances.json)
  expect("${_o}" "tolerances: ${WORK}/shared/tolerances.json \\(given\\)" "a file given")
elseif(CASE STREQUAL "golden_link")
  file(MAKE_DIRECTORY ${WORK}/set/scenes ${WORK}/outside)
  file(COPY_FILE ${SCENE} ${WORK}/set/scenes/tiny.json)
  # LINK (SET/golden/reference, then SET/golden) points to WORK/outside:
  # golden update refuses it and writes nothing there.
  function(refused_through_link link)
    file(REMOVE_RECURSE ${WORK}/set/golden)
    get_filename_component(_parent ${link} DIRECTORY)
    file(MAKE_DIRECTORY ${_parent})
    file(CREATE_LINK ${WORK}/outside ${link} SYMBOLIC)
    run_xval(2 _o golden update ${WORK}/set/scenes)
    expect("${_o}" "${link}: is a symbolic link" "golden update through the linked folder ${link}")
    file(GLOB _written ${WORK}/outside/*)
    if(_written)
      message(FATAL_ERROR "golden_link: written through the link ${link}: ${_written}")
    endif()
  endfunction()
  refused_through_link(${WORK}/set/golden/reference)
  refused_through_link(${WORK}/set/golden)
elseif(CASE STREQUAL "bench_scratch")
  file(MAKE_DIRECTORY ${WORK}/def ${WORK}/tmp)
  # The stand-in records its {work} folder and the mode of the folder two
  # levels up (the scratch folder bench made), then writes a grey image.
  file(WRITE ${WORK}/def/record.sh "#!/bin/sh
if [ \"$1\" = --version ]; then echo recorder 1.0; exit 0; fi
echo \"$1\" > ${WORK}/record.txt
stat -c %a \"$(dirname \"$(dirname \"$1\")\")\" >> ${WORK}/record.txt
exec oiiotool --pattern constant:color=0.5,0.5,0.5,1 \"$3x$4\" 4 -d float -o \"$2\"
")
  file(CHMOD ${WORK}/def/record.sh PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
  file(WRITE ${WORK}/def/recorder.json "{\"format\": \"xval-renderer/1\", \"name\": \"recorder\", \"input\": \"scene\",
 \"command\": [\"./record.sh\", \"{work}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./record.sh\", \"--version\"]}\n")
  set(ENV{TMPDIR} ${WORK}/tmp)
  run_xval(0 _o bench ${SCENE} --renderers recorder --renderer-file ${WORK}/def/recorder.json --runs 1 --frames 1)
  file(READ ${WORK}/record.txt _record)
  # bench gives a renderer its scratch folder's work/scratch (validate/bench/run.cpp).
  set(_bench_work "work/scratch")
  expect("${_record}" "^${WORK}/tmp/xval-bench-recorder-[A-Za-z0-9]+/${_bench_work}\n700\n$"
         "bench: the renderer's work folder in a private scratch folder")
  file(GLOB _left ${WORK}/tmp/*)
  if(_left)
    message(FATAL_ERROR "bench_scratch: left in TMPDIR: ${_left}")
  endif()
elseif(CASE STREQUAL "reserved_names")
  foreach(_name mine golden-mine povray)
    file(WRITE ${WORK}/${_name}.json "{\"format\": \"xval-renderer/1\", \"name\": \"${_name}\", \"input\": \"scene\",
 \"command\": [\"/bin/true\", \"{output}\"], \"version_command\": [\"/bin/true\"]}\n")
  endforeach()
  run_xval(0 _o renderers --renderer-file ${WORK}/mine.json)
  run_xval(2 _o renderers --renderer-file ${WORK}/mine.json --renderer-file ${WORK}/golden-mine.json)
  expect("${_o}" "golden-mine.json: name: \"golden-mine\": golden and the prefix golden- are reserved"
         "a renderer file named golden-mine")
  run_xval(2 _o renderers --renderer-file ${WORK}/golden-mine.json --renderer-file ${WORK}/mine.json)
  expect("${_o}" "golden-mine.json: name: \"golden-mine\": golden and the prefix golden- are reserved"
         "a renderer file named golden-mine, given first")
  run_xval(2 _o renderers --renderer-file ${WORK}/povray.json)
  expect("${_o}" "povray.json: name: \"povray\": the id of a renderer built into xval" "a renderer file named povray")
elseif(CASE STREQUAL "golden_duplicate_key")
  file(MAKE_DIRECTORY ${WORK}/set/scenes)
  file(COPY_FILE ${SCENE} ${WORK}/set/scenes/tiny.json)
  run_xval(0 _o golden update ${WORK}/set/scenes)
  set(_manifest ${WORK}/set/golden/reference/manifest.json)
  file(READ ${_manifest} _m)
  string(REPLACE "\"image_sha256\":" "\"image_sha256\": \"0000000000000000000000000000000000000000000000000000000000000000\",\n      \"image_sha256\":"
         _m "${_m}")
  file(WRITE ${_manifest} "${_m}")
  run_xval(2 _o golden check ${WORK}/set/scenes)
  expect("${_o}" "manifest.json: not valid JSON in field entries.tiny.image_sha256: duplicate field \"image_sha256\""
         "golden check of a manifest with a key twice")
elseif(CASE STREQUAL "golden_sparse")
  file(MAKE_DIRECTORY ${WORK}/set/scenes)
  file(COPY_FILE ${SCENE} ${WORK}/set/scenes/tiny.json)
  run_xval(0 _o golden update ${WORK}/set/scenes)
  sh(truncate -s 256G ${WORK}/set/golden/reference/tiny.exr)
  set(XVAL_RUN_TIMEOUT 20)
  run_xval(1 _o golden check ${WORK}/set/scenes)
  expect("${_o}" "golden/reference/tiny.exr cannot be used: .*tiny.exr: holds more than the [0-9]+ bytes expected"
         "golden check of a stored image grown to a 256 GiB sparse file")
else()
  message(FATAL_ERROR "hostile_paths.cmake: unknown CASE ${CASE}")
endif()
