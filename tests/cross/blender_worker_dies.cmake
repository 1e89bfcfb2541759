# Blender's persistent worker dying on one scene of a batch: three scenes in
# one batch (--batch 3, renderers reference and blender), the worker killed
# (SIGKILL, tests/cross/blender_worker_killer.py) when it starts the second.
# Expected: exit 2 (an error); the second scene's blender record holds the
# error "killed by signal 9 ... while rendering this scene"; the first and
# third scenes' blender records are ok (the third rendered by a fresh
# process: two worker logs); the first scene's image is the one an unbatched
# run renders.
# -DXVAL=... -DOUT=... -DSCRIPT=... -DKILLER=... -DSCENES="a.json;b.json;c.json"
find_program(IDIFF idiff REQUIRED)
file(REMOVE_RECURSE ${OUT})
list(GET SCENES 1 victim)
get_filename_component(victim ${victim} NAME_WE)
execute_process(COMMAND ${CMAKE_COMMAND} -E env XVAL_BLENDER_SCRIPT=${KILLER} XVAL_REAL_BLENDER_SCRIPT=${SCRIPT}
                        XVAL_KILL_ON=/${victim}/
                        ${XVAL} validate -o ${OUT}/killed --renderers reference,blender --batch 3 -- ${SCENES}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "expected exit 2 (the killed scene is an error), got ${rc}:\n${out}${err}")
endif()
set(index 0)
foreach(scene IN LISTS SCENES)
  get_filename_component(name ${scene} NAME_WE)
  file(READ ${OUT}/killed/${name}/blender.job.json record)
  # An ok record has no error member.
  string(JSON error ERROR_VARIABLE no_error GET "${record}" error)
  if(no_error)
    set(error "")
  endif()
  if(name STREQUAL victim)
    if(NOT error MATCHES "killed by signal 9" OR NOT error MATCHES "while rendering this scene")
      message(FATAL_ERROR "${name}: expected the worker's death as this scene's error, got: ${error}")
    endif()
  elseif(NOT error STREQUAL "")
    message(FATAL_ERROR "${name}: expected ok (only ${victim} was killed), got: ${error}")
  endif()
endforeach()
list(GET SCENES 0 first)
get_filename_component(first ${first} NAME_WE)
file(GLOB logs ${OUT}/killed/${first}/blender.work/blender-worker-*.log)
list(LENGTH logs n)
if(NOT n EQUAL 2)
  message(FATAL_ERROR "expected two worker processes (the second for the scene after the killed one), found ${n} logs")
endif()
list(GET SCENES 0 first_file)
execute_process(COMMAND ${XVAL} validate -o ${OUT}/single --renderers reference,blender --batch 1 -- ${first_file}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
execute_process(COMMAND ${IDIFF} -fail 0 -warn 0 ${OUT}/killed/${first}/blender.exr ${OUT}/single/${first}/blender.exr
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${first}: the image rendered in the batch differs from an unbatched render:\n${out}${err}")
endif()
