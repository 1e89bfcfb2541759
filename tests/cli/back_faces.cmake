# Skipping back faces (geometry/front_faces.h) changes no final pixel: every
# reference scene and every extremes case (written by `xval extremes
# --no-external` at 64 x 64), in float and double, rendered with and
# without `--keep-back-faces`, has bit-identical RGBA (idiff, no threshold).
# Diagnostics are off: at an exact tie between two adjacent front faces the
# double path may report the other triangle when the BVH changes, which the
# incidence channel shows (docs/performance.md). Also checks that some
# scenes did skip back faces, so the comparison is not vacuous.
# The scenes are split into SHARDS parts by their index in the sorted list
# (SHARD = 0..SHARDS-1), so each part is one CTest test with its own time-out:
# under AddressSanitizer on a 2-core machine the whole set takes over 600 s.
# Arguments: XVAL, SCENES (reference/scenes), WORK, SHARD, SHARDS.
foreach(_v XVAL SCENES WORK SHARD SHARDS)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "back_faces.cmake: -D${_v}=... is required")
  endif()
endforeach()
find_program(IDIFF idiff REQUIRED)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
# Each command has its own time-out (a render here takes under 2 s, 10 s
# under the sanitizers), so a hang names its scene instead of using up the
# test's time-out.
set(_cmd_timeout 120)
execute_process(COMMAND ${XVAL} extremes -o ${WORK}/extremes --no-external --size 64
                RESULT_VARIABLE _rc ERROR_VARIABLE _err TIMEOUT 300)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "xval extremes exited ${_rc}:\n${_err}")
endif()
file(GLOB _all ${SCENES}/*.json ${WORK}/extremes/scenes/*.json)
list(SORT _all)
list(LENGTH _all _n)
if(_n LESS 40)
  message(FATAL_ERROR "expected the reference scenes and the extremes cases, at least 40, found ${_n} scenes")
endif()
if(NOT SHARDS GREATER 0 OR SHARD LESS 0 OR NOT SHARD LESS SHARDS)
  message(FATAL_ERROR "back_faces.cmake: SHARD=${SHARD} must be in 0..SHARDS-1 (SHARDS=${SHARDS})")
endif()
set(_scenes "")
set(_i 0)
foreach(_scene ${_all})
  math(EXPR _part "${_i} % ${SHARDS}")
  if(_part EQUAL SHARD)
    list(APPEND _scenes ${_scene})
  endif()
  math(EXPR _i "${_i} + 1")
endforeach()
list(LENGTH _scenes _mine)
set(_skipping 0)
foreach(_scene ${_scenes})
  get_filename_component(_name ${_scene} NAME_WE)
  foreach(_p float double)
    set(_a ${WORK}/${_name}.${_p}.exr)
    set(_b ${WORK}/${_name}.${_p}.kept.exr)
    execute_process(COMMAND ${XVAL} render ${_scene} -o ${_a} --precision ${_p} --no-diagnostics -q
                            --stats ${WORK}/${_name}.${_p}.json
                    RESULT_VARIABLE _rc1 ERROR_VARIABLE _e1 TIMEOUT ${_cmd_timeout})
    execute_process(COMMAND ${XVAL} render ${_scene} -o ${_b} --precision ${_p} --no-diagnostics -q
                            --keep-back-faces
                    RESULT_VARIABLE _rc2 ERROR_VARIABLE _e2 TIMEOUT ${_cmd_timeout})
    if(NOT _rc1 EQUAL 0 OR NOT _rc2 EQUAL 0)
      message(FATAL_ERROR "${_name} (${_p}): render failed (exit ${_rc1} without, ${_rc2} with --keep-back-faces; "
                          "'Process terminated due to timeout' is the ${_cmd_timeout} s time-out):\n${_e1}\n${_e2}")
    endif()
    file(READ ${WORK}/${_name}.${_p}.json _stats)
    string(JSON _culled GET "${_stats}" culled_triangles)
    if(_culled GREATER 0)
      math(EXPR _skipping "${_skipping} + 1")
    endif()
    execute_process(COMMAND ${IDIFF} -a -fail 0 -warn 0 ${_a} ${_b}
                    RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _out TIMEOUT ${_cmd_timeout})
    if(NOT _rc EQUAL 0)
      message(FATAL_ERROR "${_name} (${_p}): skipping ${_culled} back faces changed the image:\n${_out}")
    endif()
  endforeach()
endforeach()
# Over the whole set 82 of the 136 renders skip back faces; each part must
# have at least 40 of them in proportion, or the comparison is too weak.
math(EXPR _need "40 / ${SHARDS}")
if(_skipping LESS _need)
  message(FATAL_ERROR "only ${_skipping} renders of part ${SHARD} skipped any back face (need ${_need}): the comparison is too weak")
endif()
message(STATUS "part ${SHARD}/${SHARDS}: ${_mine} of ${_n} scenes x 2 precisions identical; ${_skipping} renders skipped back faces")
