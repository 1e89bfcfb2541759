cmake_minimum_required(VERSION 3.20)
# Faults of the file system, of processes and of hostile names and paths,
# through the real xval with stand-in tools. One CASE per test:
#   record_on_full_disk     the disk fills while a job runs (the stand-in
#                           povray fills a small tmpfs): validate exits 2 with
#                           the write error, never aborts; no verdict left
#   readonly_case_folder    the case folder is a read-only bind mount:
#                           validate exits 2 naming the read-only folder
#   reserved_scene_names    scenes named like validate's own files, or with
#                           '?' or '\': refused before anything is rendered
#   interrupt               SIGINT to validate while the tools run: no tool
#                           survives, nothing is written afterwards
#   resume_ignores_orphan   a run killed (SIGKILL) leaves a povray that writes
#                           its image later; a --resume whose povray writes
#                           nothing must not take that image
#   lock                    a second validate into the same folder while the
#                           first runs: refused, naming the folder and the pid
#   stale_report            a rerun that is killed leaves no report.html or
#                           results.json of the run before
#   planted_symlinks        links planted at povray.work/README.txt,
#                           povray.work/povray.log, blender.work/scene.gltf and
#                           a case folder that is a link: nothing is written
#                           through them
#   hostile_output_folder   an output folder with ' or \: refused before any
#                           tool runs
#   generate_on_full_disk   `xval generate` and `xval export pov` on a full
#                           tmpfs: exit 1 naming the file, no partial file
#                           under a final name
#   not_a_regular_file      --stats to a device node like /dev/full (or a
#                           link to it): refused, the node kept
# Arguments: XVAL, SCENE (tests/cli/scenes/tiny.json), SPEC (a generator
# spec), WORK (scratch folder), CASE.
# The mount cases need root (mount in a private namespace, `unshare -m`);
# they fail, never skip, when that is not possible.
foreach(_v XVAL SCENE WORK CASE)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "faults.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin)
set(TOL ${CMAKE_CURRENT_LIST_DIR}/../../reference/tolerances.json)

function(stand_in tool body)
  file(WRITE ${WORK}/bin/${tool}
    "#!/bin/sh\nif [ \"$1\" = --version ]; then echo 'stand-in ${tool} 0.0'; exit 0; fi\nPATH=/usr/bin:/bin\n${body}\n")
  file(CHMOD ${WORK}/bin/${tool} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()
# validate's report plots with gnuplot: keep it reachable.
find_program(_gnuplot gnuplot)
if(_gnuplot)
  file(CREATE_LINK ${_gnuplot} ${WORK}/bin/gnuplot SYMBOLIC)
endif()

# Runs a shell script (PATH: the stand-ins first); sets rc, out, err.
macro(run_sh script)
  execute_process(COMMAND /bin/sh -c "${script}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("sh -c: ${script}\nexit: ${rc}\nstdout:\n${out}\nstderr:\n${err}")
endmacro()
function(require_exit want)
  if(NOT rc MATCHES "^[0-9]+$")
    message(FATAL_ERROR "did not exit normally: ${rc}")
  endif()
  if(NOT rc EQUAL want)
    message(FATAL_ERROR "exit status ${rc}, expected ${want}")
  endif()
  foreach(_s "AddressSanitizer" "LeakSanitizer" "runtime error:" "terminate called")
    string(FIND "${err}" "${_s}" _at)
    if(NOT _at EQUAL -1)
      message(FATAL_ERROR "stderr shows \"${_s}\"")
    endif()
  endforeach()
endfunction()
function(require_in text what)
  foreach(_s ${ARGN})
    string(FIND "${text}" "${_s}" _at)
    if(_at EQUAL -1)
      message(FATAL_ERROR "${what} does not contain \"${_s}\"")
    endif()
  endforeach()
endfunction()
function(require_absent)
  foreach(_f ${ARGN})
    if(EXISTS "${_f}" OR IS_SYMLINK "${_f}")
      message(FATAL_ERROR "${_f} exists")
    endif()
  endforeach()
endfunction()
# A scene file like SCENE with another name.
function(scene_named name file)
  file(READ ${SCENE} _s)
  string(JSON _s SET "${_s}" name "\"${name}\"")
  file(WRITE ${file} "${_s}")
endfunction()
function(require_unshare)
  execute_process(COMMAND unshare -m /bin/true RESULT_VARIABLE _r)
  if(NOT _r EQUAL 0)
    message(FATAL_ERROR "this test needs `unshare -m` (root) to mount a small or read-only file system")
  endif()
endfunction()

set(V "'${XVAL}' validate '${SCENE}' --tolerances '${TOL}'")
# Shell: wait (at most 60 s) until file $1 has at least $2 lines, so that a
# signal or a second run comes once the stand-ins run, however loaded the
# machine.
set(WAIT_FOR "wait_for() { i=0; while [ $i -lt 600 ] && [ \"$(cat \"$1\" 2>/dev/null | wc -l)\" -lt $2 ]; do sleep 0.1; i=$((i+1)); done; }")
set(ENVPATH "PATH='${WORK}/bin':/usr/bin:/bin")

if(CASE STREQUAL "record_on_full_disk")
  require_unshare()
  # povray fills the file system (a 1 MiB tmpfs at OUT), then fails; its
  # record and everything after cannot be written.
  stand_in(povray "head -c 4194304 /dev/zero > ../../fill 2>/dev/null\necho 'stand-in povray: disk filled'\nexit 3")
  stand_in(blender "echo 'stand-in blender: not under test'\nexit 9")
  file(MAKE_DIRECTORY ${WORK}/out)
  file(WRITE ${WORK}/run.sh "mount -t tmpfs -o size=1m tmpfs '${WORK}/out' || exit 100
${ENVPATH} ${V} -o '${WORK}/out' --jobs 1 --timeout 30
echo exit=$? >&2
ls -A '${WORK}/out' > '${WORK}/left'
")
  run_sh("unshare -m /bin/sh '${WORK}/run.sh'")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the mount namespace could not be set up (${rc})")
  endif()
  string(REGEX MATCH "exit=([0-9]+)" _m "${err}")
  set(rc "${CMAKE_MATCH_1}")
  require_exit(2)
  require_in("${err}" "stderr" "povray.job.json: cannot write" "No space left on device")
  file(STRINGS ${WORK}/left _left)
  message("left in the output folder: ${_left}")
  foreach(_f results.json report.html)
    if(_f IN_LIST _left)
      message(FATAL_ERROR "a ${_f} was left on the full disk")
    endif()
  endforeach()

elseif(CASE STREQUAL "readonly_case_folder")
  require_unshare()
  stand_in(povray "echo 'stand-in povray: not under test'\nexit 9")
  stand_in(blender "echo 'stand-in blender: not under test'\nexit 9")
  file(MAKE_DIRECTORY ${WORK}/out/tiny)
  file(WRITE ${WORK}/run.sh "mount --bind '${WORK}/out/tiny' '${WORK}/out/tiny' || exit 100
mount -o remount,bind,ro '${WORK}/out/tiny' || exit 101
${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 30
echo exit=$? >&2
")
  run_sh("unshare -m /bin/sh '${WORK}/run.sh'")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the mount namespace could not be set up (${rc})")
  endif()
  string(REGEX MATCH "exit=([0-9]+)" _m "${err}")
  set(rc "${CMAKE_MATCH_1}")
  require_exit(2)
  require_in("${err}" "stderr" "reference.job.json: cannot write" "povray.job.json: cannot write"
             "blender.job.json: cannot write" "Read-only file system" "ERRORS")
  file(READ ${WORK}/out/results.json _results)
  string(JSON _e GET "${_results}" cases 0 renders reference error)
  require_in("${_e}" "results.json's reference error" "no record")

elseif(CASE STREQUAL "reserved_scene_names")
  stand_in(povray "touch '${WORK}/ran-povray'\nexit 9")
  stand_in(blender "touch '${WORK}/ran-blender'\nexit 9")
  foreach(_name jobs.json results.json report.html p999.png p999.dat heat_scale.png version.log .xval.lock
                extremes tradeoff "results.json.partial-1-2" "what?" "a\\\\..\\\\..\\\\up")
    string(MAKE_C_IDENTIFIER "${_name}" _id)
    scene_named("${_name}" ${WORK}/${_id}.json)
    run_sh("${ENVPATH} '${XVAL}' validate '${WORK}/${_id}.json' -o '${WORK}/out_${_id}' --tolerances '${TOL}'")
    require_exit(2)
    if(_name MATCHES "[?\\\\]")
      require_in("${err}" "stderr" "name: expected a name without '\\' or '?'")
    else()
      require_in("${err}" "stderr" "cannot name a case folder" "uses in its output folder")
    endif()
    require_absent(${WORK}/out_${_id}/jobs.json ${WORK}/ran-povray ${WORK}/ran-blender)
  endforeach()

elseif(CASE STREQUAL "interrupt")
  # Every tool records its pid, sleeps, then writes a file (its own and
  # one in the output folder); SIGINT reaches xval once two run (POV-Ray's
  # job and a Blender worker; EEVEE's worker may have started too).
  foreach(_t povray blender)
    stand_in(${_t} "echo $$ >> '${WORK}/pids'\nsleep 4\ntouch '${WORK}/late-${_t}-'$$ late-${_t}\nexit 0")
  endforeach()
  run_sh("${WAIT_FOR}; ${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60 & p=$!; wait_for '${WORK}/pids' 2; kill -INT $p; wait $p; echo rc=$?")
  string(REGEX MATCH "rc=([0-9]+)" _m "${out}")
  set(rc "${CMAKE_MATCH_1}")
  execute_process(COMMAND sleep 5)  # past the stand-ins' sleep
  file(STRINGS ${WORK}/pids _pids)
  list(LENGTH _pids _n)
  if(_n LESS 2)
    message(FATAL_ERROR "expected at least two stand-ins to have started, got pids: ${_pids}")
  endif()
  foreach(_p ${_pids})
    execute_process(COMMAND kill -0 ${_p} RESULT_VARIABLE _alive ERROR_QUIET)
    if(_alive EQUAL 0)
      execute_process(COMMAND kill -KILL -${_p} ERROR_QUIET)
      message(FATAL_ERROR "stand-in pid ${_p} still runs after xval was interrupted")
    endif()
  endforeach()
  file(GLOB_RECURSE _late ${WORK}/late-* ${WORK}/out/late-*)
  if(_late)
    message(FATAL_ERROR "written after the interrupt: ${_late}")
  endif()
  require_absent(${WORK}/out/results.json ${WORK}/out/report.html)
  require_in("${err}" "stderr" "xval: interrupted")
  if(NOT rc EQUAL 130)
    message(FATAL_ERROR "exit status ${rc}, expected 130 (died of SIGINT)")
  endif()

elseif(CASE STREQUAL "resume_ignores_orphan")
  # A 16x16 PNG with alpha, as POV-Ray writes it.
  find_program(_oiiotool oiiotool REQUIRED)
  execute_process(COMMAND ${_oiiotool} --pattern constant:color=0.5,0.5,0.5,1 16x16 4 -d uint16
                          -o ${WORK}/image.png RESULT_VARIABLE _r)
  if(NOT _r EQUAL 0)
    message(FATAL_ERROR "oiiotool could not make the image")
  endif()
  # First run: povray sleeps 3 s, then writes its image and exits 0; xval
  # is killed (SIGKILL: nothing can stop the stand-in) once it runs. Second run
  # (--resume): povray writes nothing, sleeps past the orphan's write, and
  # exits 0.
  stand_in(povray "out=$(sed -n 's/^Output_File_Name=//p' scene.ini)\nfor a in \"$@\"; do o=$(echo \"$a\" | /bin/sed -n 's/^+O//p'); [ -z \"$o\" ] || out=$o; done\nif [ ! -e '${WORK}/first' ]; then echo started > '${WORK}/first'; sleep 3; cp '${WORK}/image.png' \"$out\" && touch '${WORK}/orphan-wrote'; exit 0; fi\nsleep 5\nexit 0")
  stand_in(blender "echo 'stand-in blender: not under test'\nexit 9")
  run_sh("${WAIT_FOR}; ${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60 & p=$!; wait_for '${WORK}/first' 1; kill -KILL $p; wait $p; ${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60 --resume")
  require_exit(2)
  if(NOT EXISTS ${WORK}/first)
    message(FATAL_ERROR "the first povray did not start")
  endif()
  file(READ ${WORK}/out/results.json _results)
  string(JSON _e ERROR_VARIABLE _none GET "${_results}" cases 0 renders povray error)
  if(_none)
    message(FATAL_ERROR "the resumed povray job took an image it did not write (no error recorded)")
  endif()
  require_in("${_e}" "results.json's povray error" "exited 0 but wrote no image")

elseif(CASE STREQUAL "lock")
  stand_in(povray "echo $$ >> '${WORK}/started'\nsleep 3\nexit 9")
  stand_in(blender "exit 9")
  run_sh("${WAIT_FOR}; ${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60 2> '${WORK}/first.err' & p=$!; wait_for '${WORK}/started' 1; ${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60; echo second=$? pid=$p; wait $p; echo first=$?")
  require_in("${out}" "stdout" "second=2" "first=2")
  string(REGEX MATCH "pid=([0-9]+)" _m "${out}")
  require_in("${err}" "the second run's stderr" "${WORK}/out: another xval validate is writing into this folder (pid ${CMAKE_MATCH_1}")
  file(READ ${WORK}/first.err _first)
  require_in("${_first}" "the first run's stderr" "xval validate: 1 scene, ERRORS")
  # --plan-only and --compare-only are refused the same way.
  run_sh("${WAIT_FOR}; ${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60 > /dev/null 2>&1 & p=$!; wait_for '${WORK}/started' 2; ${ENVPATH} '${XVAL}' validate --plan '${WORK}/out/jobs.json' --compare-only; echo second=$?; wait $p")
  require_in("${out}" "stdout" "second=2")
  require_in("${err}" "stderr" "another xval validate is writing into this folder")

elseif(CASE STREQUAL "stale_report")
  stand_in(povray "if [ -e '${WORK}/slow' ]; then echo $$ > '${WORK}/slow_pid'; exec sleep 30; fi\nexit 9")
  stand_in(blender "exit 9")
  run_sh("${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60")
  require_exit(2)
  if(NOT EXISTS ${WORK}/out/report.html OR NOT EXISTS ${WORK}/out/results.json)
    message(FATAL_ERROR "the first run wrote no report")
  endif()
  # The rerun is killed while povray runs.
  file(WRITE ${WORK}/slow "")
  run_sh("${WAIT_FOR}; ${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60 & p=$!; wait_for '${WORK}/slow_pid' 1; kill -KILL $p; wait $p; sleep 0.2")
  require_absent(${WORK}/out/report.html ${WORK}/out/results.json)
  # The stand-in SIGKILL left running (exec'd into sleep, same pid).
  if(EXISTS ${WORK}/slow_pid)
    file(STRINGS ${WORK}/slow_pid _p)
    execute_process(COMMAND kill -KILL ${_p} ERROR_QUIET)
  endif()

elseif(CASE STREQUAL "planted_symlinks")
  stand_in(povray "echo 'stand-in povray: not under test'\nexit 9")
  stand_in(blender "echo 'stand-in blender: not under test'\nexit 9")
  file(MAKE_DIRECTORY ${WORK}/out/tiny/povray.work ${WORK}/out/tiny/blender.work ${WORK}/elsewhere)
  foreach(_v readme log gltf)
    file(WRITE ${WORK}/victim_${_v} "precious\n")
  endforeach()
  file(CREATE_LINK ${WORK}/victim_readme ${WORK}/out/tiny/povray.work/README.txt SYMBOLIC)
  file(CREATE_LINK ${WORK}/victim_log ${WORK}/out/tiny/povray.work/povray.log SYMBOLIC)
  file(CREATE_LINK ${WORK}/victim_gltf ${WORK}/out/tiny/blender.work/scene.gltf SYMBOLIC)
  run_sh("${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60")
  require_exit(2)
  require_in("${err}" "stderr" "exit code 9")
  foreach(_v readme log gltf)
    file(READ ${WORK}/victim_${_v} _c)
    if(NOT _c STREQUAL "precious\n")
      message(FATAL_ERROR "written through the planted link to victim_${_v}: now \"${_c}\"")
    endif()
  endforeach()
  # A case folder that is a link to elsewhere: refused, nothing written there.
  file(REMOVE_RECURSE ${WORK}/out)
  file(MAKE_DIRECTORY ${WORK}/out)
  file(CREATE_LINK ${WORK}/elsewhere ${WORK}/out/tiny SYMBOLIC)
  run_sh("${ENVPATH} ${V} -o '${WORK}/out' --jobs 3 --timeout 60")
  require_exit(2)
  require_in("${err}" "stderr" "${WORK}/out/tiny: " "case folder is a symbolic link")
  file(GLOB _there ${WORK}/elsewhere/*)
  if(_there)
    message(FATAL_ERROR "written through the case folder link: ${_there}")
  endif()

elseif(CASE STREQUAL "hostile_output_folder")
  stand_in(povray "touch '${WORK}/ran-povray'\nexit 9")
  stand_in(blender "touch '${WORK}/ran-blender'\nexit 9")
  foreach(_dir "a\\\\b" "x?y")
    run_sh("${ENVPATH} ${V} -o \"${WORK}/${_dir}/out\" --jobs 3 --timeout 60")
    require_absent(${WORK}/ran-povray ${WORK}/ran-blender)
    require_exit(2)
    require_in("${err}" "stderr" "cannot be used as an output folder: it contains")
    file(GLOB _made "${WORK}/*/out/jobs.json")
    if(_made)
      message(FATAL_ERROR "validate planned into ${_made}")
    endif()
  endforeach()
  # A quote is no longer special (gnuplot runs without a shell): the run
  # completes, plot included.
  run_sh("${ENVPATH} ${V} -o \"${WORK}/it's/out\" --jobs 3 --timeout 60")
  require_exit(2)
  file(REMOVE ${WORK}/ran-povray ${WORK}/ran-blender)
  if(NOT EXISTS "${WORK}/it's/out/p999.png" OR NOT EXISTS "${WORK}/it's/out/report.html")
    message(FATAL_ERROR "no plot or report in a folder named with a quote")
  endif()
  # The Blender harness refuses a '\\' in its paths wherever it is called from.
  stand_in(blender "touch '${WORK}/ran-blender'\nexit 9")
  run_sh("${ENVPATH} '${XVAL}' render '${SCENE}' --renderer blender -o \"${WORK}/b\\\\c/x.exr\" --timeout 60")
  require_absent(${WORK}/ran-blender)
  require_exit(2)
  require_in("${err}" "stderr" "which Blender reads as a folder separator")

elseif(CASE STREQUAL "generate_on_full_disk")
  require_unshare()
  if(NOT DEFINED SPEC)
    message(FATAL_ERROR "faults.cmake: -DSPEC=... is required")
  endif()
  file(MAKE_DIRECTORY ${WORK}/mnt)
  # 8 KiB: the first scene files fit, the rest do not; scene.pov of a
  # textured knot does not fit at all.
  set(_knot ${CMAKE_CURRENT_LIST_DIR}/../../reference/scenes/table2_knot_yiq.json)
  file(WRITE ${WORK}/run.sh "mount -t tmpfs -o size=8k tmpfs '${WORK}/mnt' || exit 100
'${XVAL}' generate '${SPEC}' -o '${WORK}/mnt/gen'
echo generate=$? >&2
'${XVAL}' export pov '${_knot}' -o '${WORK}/mnt/pov'
echo export=$? >&2
cp -a '${WORK}/mnt' '${WORK}/copy'
")
  run_sh("unshare -m /bin/sh '${WORK}/run.sh'")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the mount namespace could not be set up (${rc})")
  endif()
  file(GLOB _gen LIST_DIRECTORIES true ${WORK}/copy/gen/*)
  file(GLOB _pov LIST_DIRECTORIES true ${WORK}/copy/pov/*)
  message("left: ${_gen} ${_pov}")
  foreach(_f ${_gen} ${_pov})
    if(IS_DIRECTORY ${_f})
      message(FATAL_ERROR "a temporary folder left behind: ${_f}")
    endif()
    file(SIZE ${_f} _size)
    if(_size EQUAL 0)
      message(FATAL_ERROR "a 0-byte file under a final name: ${_f}")
    endif()
    if(_f MATCHES "[.]json$")
      file(READ ${_f} _text)
      string(JSON _fmt ERROR_VARIABLE _jerr GET "${_text}" format)
      if(_jerr)
        message(FATAL_ERROR "a truncated scene file under a final name: ${_f}: ${_jerr}")
      endif()
    endif()
  endforeach()
  if(EXISTS ${WORK}/copy/pov/scene.pov)
    message(FATAL_ERROR "scene.pov was written although it cannot fit in 8 KiB")
  endif()
  require_in("${err}" "stderr" "generate=2" "export=2" "No space left on device" ": cannot write")
  list(LENGTH _gen _ngen)
  if(_ngen EQUAL 0)
    message(FATAL_ERROR "no scene fitted: the test shows nothing about partial files")
  endif()

elseif(CASE STREQUAL "not_a_regular_file")
  # A target that is a device (or a link to one) is refused: a file is
  # written whole by renaming a temporary over it, which must never replace
  # a device, and writing into /dev/full would report success for nothing
  # kept. The device is the test's own node with /dev/full's numbers
  # (char 1 7): were the check broken, only that node would be replaced.
  execute_process(COMMAND mknod ${WORK}/full c 1 7 RESULT_VARIABLE _r)
  if(NOT _r EQUAL 0)
    message(FATAL_ERROR "this test needs mknod (root) to make a device node like /dev/full")
  endif()
  file(CREATE_LINK ${WORK}/full ${WORK}/link_to_full SYMBOLIC)
  foreach(_target ${WORK}/full ${WORK}/link_to_full)
    run_sh("'${XVAL}' render '${SCENE}' -o '${WORK}/x.exr' -q --stats '${_target}'")
    execute_process(COMMAND stat -c %F ${WORK}/full OUTPUT_VARIABLE _kind)
    require_in("${_kind}" "the device node's type" "character special file")
    require_exit(2)
    require_in("${err}" "stderr" "${_target}: cannot write: it exists and is not a regular file")
  endforeach()
  if(NOT IS_SYMLINK ${WORK}/link_to_full)
    message(FATAL_ERROR "the link was replaced")
  endif()

else()
  message(FATAL_ERROR "faults.cmake: unknown CASE=${CASE}")
endif()
