# A sampled subset of the coverage matrix (tests/coverage/scene_matrix.json)
# cross-rendered: every STEP-th scene in name order (starting at the first)
# whose POV-Ray export succeeds (a refused scene is replaced by the next
# one), copied into one folder and validated there with every renderer.
# Fails unless `xval validate` exits 0 and at least MIN scenes were checked.
# Args: XVAL, SPEC, TOLERANCES, TEXTURES (reference/textures), WORK, STEP, MIN.
#
# The generated scenes keep the spec's relative texture path
# (../../reference/textures/...): they are written two levels below WORK,
# beside a copy of the textures at WORK/reference/textures.
file(REMOVE_RECURSE ${WORK})
file(COPY ${TEXTURES} DESTINATION ${WORK}/reference)
execute_process(COMMAND ${XVAL} generate ${SPEC} -o ${WORK}/scenes/all RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "xval generate ${SPEC}: exit ${rc}")
endif()
file(GLOB scenes ${WORK}/scenes/all/*.json)
list(SORT scenes)
list(LENGTH scenes n)
set(picked 0)
set(next 0)
set(i 0)
foreach(scene IN LISTS scenes)
  if(i GREATER_EQUAL next)
    get_filename_component(name ${scene} NAME_WE)
    execute_process(COMMAND ${XVAL} export pov ${scene} -o ${WORK}/export/${name}
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
    if(rc EQUAL 0)
      file(COPY ${scene} DESTINATION ${WORK}/scenes/subset)
      math(EXPR picked "${picked} + 1")
      math(EXPR next "${next} + ${STEP}")
    else()
      message(STATUS "not expressible by POV-Ray, the next one instead: ${name}")
    endif()
  endif()
  math(EXPR i "${i} + 1")
endforeach()
message(STATUS "${picked} of ${n} scenes picked")
if(picked LESS MIN)
  message(FATAL_ERROR "only ${picked} scenes picked, expected at least ${MIN}")
endif()
execute_process(COMMAND ${XVAL} validate ${WORK}/scenes/subset --tolerances ${TOLERANCES} -o ${WORK}/validate
                RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "xval validate of the ${picked} sampled scenes: exit ${rc} (see ${WORK}/validate/report.html)")
endif()
