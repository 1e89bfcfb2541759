# Opens REPORT in headless Chromium in a WINDOW (default 1280,2000) wide
# and high window: fails unless the page's title then matches TITLE
# (default "images OK": the page's own check that every <img> decoded);
# saves a screenshot as SHOT. Also include()d by scripts that set these.
find_program(CHROMIUM chromium REQUIRED)
if(NOT DEFINED TITLE)
  set(TITLE "images OK")
endif()
if(NOT DEFINED WINDOW)
  set(WINDOW 1280,2000)
endif()
if(NOT EXISTS ${REPORT})
  message(FATAL_ERROR "${REPORT} does not exist")
endif()
set(flags --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
    --disable-background-networking --disable-component-update --disable-sync --window-size=${WINDOW})
get_filename_component(dir ${SHOT} DIRECTORY)
set(profile ${dir}/chromium-profile)
file(REMOVE_RECURSE ${profile})
execute_process(COMMAND ${CHROMIUM} ${flags} --user-data-dir=${profile} --virtual-time-budget=10000
                        --dump-dom file://${REPORT}
                OUTPUT_VARIABLE dom ERROR_VARIABLE err RESULT_VARIABLE rc TIMEOUT 120)
string(REGEX MATCH "<title>[^<]*</title>" title "${dom}")
message(STATUS "chromium: ${title}")
if(NOT rc EQUAL 0 OR NOT title MATCHES "${TITLE}")
  message(FATAL_ERROR "report check failed (exit ${rc}; expected a title matching \"${TITLE}\"): ${title}\n${err}")
endif()
file(REMOVE ${SHOT})
execute_process(COMMAND ${CHROMIUM} ${flags} --user-data-dir=${profile} --virtual-time-budget=10000
                        --screenshot=${SHOT} file://${REPORT}
                RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 120)
if(NOT rc EQUAL 0 OR NOT EXISTS ${SHOT})
  message(FATAL_ERROR "chromium screenshot failed (exit ${rc}): ${err}")
endif()
file(REMOVE_RECURSE ${profile})
