# Opens REPORT in headless Chromium: fails unless the page's own check
# (every <img> decoded) put "images OK" in its title; saves a screenshot.
find_program(CHROMIUM chromium REQUIRED)
if(NOT EXISTS ${REPORT})
  message(FATAL_ERROR "${REPORT} does not exist")
endif()
set(flags --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
    --disable-background-networking --disable-component-update --disable-sync)
get_filename_component(dir ${SHOT} DIRECTORY)
set(profile ${dir}/chromium-profile)
file(REMOVE_RECURSE ${profile})
execute_process(COMMAND ${CHROMIUM} ${flags} --user-data-dir=${profile} --virtual-time-budget=10000
                        --dump-dom file://${REPORT}
                OUTPUT_VARIABLE dom ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 120)
string(REGEX MATCH "<title>[^<]*</title>" title "${dom}")
message(STATUS "chromium: ${title}")
if(NOT rc EQUAL 0 OR NOT title MATCHES "images OK")
  message(FATAL_ERROR "report check failed (exit ${rc}): ${title}\n${err}")
endif()
file(REMOVE ${SHOT})
execute_process(COMMAND ${CHROMIUM} ${flags} --user-data-dir=${profile} --window-size=1280,2000
                        --screenshot=${SHOT} file://${REPORT}
                RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0 OR NOT EXISTS ${SHOT})
  message(FATAL_ERROR "chromium screenshot failed (exit ${rc}): ${err}")
endif()
file(REMOVE_RECURSE ${profile})
