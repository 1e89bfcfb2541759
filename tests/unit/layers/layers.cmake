# scripts/check-layers.py on the repository (no include climbs to a module
# above its own), and on a made-up tree where one does, which it must
# refuse, naming the file and line: the check can fail.
# -DPYTHON, -DSCRIPT, -DREPO, -DWORK
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${REPO} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "check-layers on the repository: exit ${rc}\n${out}${err}")
endif()
if(NOT out MATCHES "no include climbs")
  message(FATAL_ERROR "check-layers said nothing of the repository: ${out}")
endif()

file(REMOVE_RECURSE ${WORK})
file(WRITE ${WORK}/renderer/render/ray.h "#pragma once\n")
file(WRITE ${WORK}/renderer/scene/scene.h "#pragma once\n// the data\n#include \"render/ray.h\"\n")
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 1 OR NOT out MATCHES "renderer/scene/scene.h:3: module scene .* includes render/ray.h of module render")
  message(FATAL_ERROR "check-layers passed a scene header including the renderer: exit ${rc}\n${out}${err}")
endif()

file(WRITE ${WORK}/renderer/newfolder/x.h "#pragma once\n")
execute_process(COMMAND ${PYTHON} ${SCRIPT} ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 2 OR NOT out MATCHES "the module newfolder is in no layer")
  message(FATAL_ERROR "check-layers passed a folder in no layer: exit ${rc}\n${out}${err}")
endif()
