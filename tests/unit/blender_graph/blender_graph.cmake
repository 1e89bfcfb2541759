# unit.blender_graph: writes the cases (glTF exports + reference colours at
# sample points) and evaluates the Blender script's node graph on them.
if(NOT PYTHON OR PYTHON MATCHES "NOTFOUND$")
  message(FATAL_ERROR "python3 not found: the node-graph check cannot run")
endif()
execute_process(COMMAND ${SAMPLES} ${WORK} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err TIMEOUT 200)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${SAMPLES} ${WORK} failed (${rc})")
endif()
execute_process(COMMAND ${PYTHON} ${CHECK} ${SCRIPT} ${WORK}/cases.json RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 200)
message("${out}${err}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the Blender node graph disagrees with the reference shader (exit ${rc})")
endif()
