# Blender's persistent worker (blender/blender_render.h renderBlenderBatch)
# against one Blender process per scene: the same scenes validated with
# the blender and eevee renderers twice, batched (--batch 3: all three
# scenes in one process per renderer) and unbatched (--batch 1 --schedule
# count, the path every job once took). results.json must agree except for
# timings (tests/cluster/compare_runs.py) and every Blender EXR must hold
# the same pixels (idiff -fail 0 -warn 0). The batched run must really have
# used one worker process per renderer (one worker log each).
# -DXVAL=... -DPYTHON=... -DCOMPARE=... -DOUT=... -DSCENES="a.json;b.json;c.json"
find_program(IDIFF idiff REQUIRED)
file(REMOVE_RECURSE ${OUT})
foreach(variant batched unbatched)
  if(variant STREQUAL "batched")
    set(flags --batch 3)
  else()
    set(flags --batch 1 --schedule count)
  endif()
  execute_process(COMMAND ${XVAL} validate -o ${OUT}/${variant} --renderers reference,blender,eevee ${flags}
                          -- ${SCENES}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${variant} run: exit ${rc} (expected 0: every scene passes):\n${out}${err}")
  endif()
endforeach()
execute_process(COMMAND ${PYTHON} ${COMPARE} ${OUT}/batched ${OUT}/unbatched
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "batched and unbatched results differ (compare_runs.py exit ${rc}):\n${out}${err}")
endif()
set(workers 0)
foreach(scene IN LISTS SCENES)
  get_filename_component(name ${scene} NAME_WE)
  foreach(renderer blender eevee)
    execute_process(COMMAND ${IDIFF} -fail 0 -warn 0 ${OUT}/batched/${name}/${renderer}.exr
                            ${OUT}/unbatched/${name}/${renderer}.exr
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      message(FATAL_ERROR "${name} ${renderer}: the batched image differs from the unbatched one:\n${out}${err}")
    endif()
    file(GLOB logs ${OUT}/batched/${name}/${renderer}.work/${renderer}-worker-*.log)
    list(LENGTH logs n)
    math(EXPR workers "${workers} + ${n}")
  endforeach()
endforeach()
if(NOT workers EQUAL 2)
  message(FATAL_ERROR "the batched run started ${workers} Blender worker processes; expected 2 (one per renderer)")
endif()
