# `xval extremes` with its default external renderers, POV-Ray, Blender and gl,
# over the whole matrix (160 x 160; POV-Ray and Blender about 1 minute on an
# idle 2-core machine, 2.5 under a load of 8; gl about as long; EEVEE, a
# Blender process per case, only when named, is not run here), then
# `xval report` on a copy of the published report folder (its PNGs and
# results.json; no EXRs needed) given the extremes folder inside it
# (--extremes).
# Checks:
#   - exit 0: no NaN/Inf in the reference renderer, and every external
#     render either succeeded or was refused by its exporter with a reason
#     (a failing, missing or hanging tool exits 2: an error, not a pass);
#   - every case has a status per external renderer, "ok" ones metrics and
#     a map, refused ones a reason starting "not renderable by";
#   - report.html has the section (the Chromium test then checks that
#     every image of the page decodes).
# Arguments: XVAL, PUBLISHED (a report folder: results.json and PNGs), WORK.
foreach(_v XVAL PUBLISHED WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "extremes.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(COPY ${PUBLISHED}/ DESTINATION ${WORK}/report
     FILES_MATCHING PATTERN "*.png" PATTERN "results.json" PATTERN "*.work" EXCLUDE
     PATTERN "extremes" EXCLUDE PATTERN "tradeoff" EXCLUDE)
# A copy of a results.json elsewhere: the section folders it records
# (relative to it) are not copied, and `xval report` refuses a named folder
# that is missing, so the copy drops them and names only this test's one.
file(READ ${WORK}/report/results.json _rj)
string(JSON _rj_stripped ERROR_VARIABLE _rj_err REMOVE "${_rj}" sections)
if(NOT _rj_err)
  file(WRITE ${WORK}/report/results.json "${_rj_stripped}")
endif()
set(_out ${WORK}/report/extremes)
execute_process(COMMAND ${XVAL} extremes -o ${_out}
                RESULT_VARIABLE _rc ERROR_VARIABLE _err OUTPUT_VARIABLE _stdout)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "xval extremes exited ${_rc} (1: NaN/Inf in the reference renderer, 2: an error):\n${_err}")
endif()
file(READ ${_out}/extremes.json _j)
string(JSON _n LENGTH "${_j}" cases)
math(EXPR _last "${_n} - 1")
foreach(_i RANGE ${_last})
  string(JSON _name GET "${_j}" cases ${_i} name)
  foreach(_r povray blender gl)
    string(JSON _status GET "${_j}" cases ${_i} external ${_r} status)
    if(_status STREQUAL "ok")
      string(JSON _map GET "${_j}" cases ${_i} external ${_r} metrics map)
      if(NOT EXISTS ${_out}/${_map})
        message(FATAL_ERROR "${_name} ${_r}: map ${_map} missing")
      endif()
    elseif(_status STREQUAL "not renderable")
      string(JSON _why GET "${_j}" cases ${_i} external ${_r} reason)
      if(NOT _why MATCHES "^not renderable by (POV-Ray|Blender|EEVEE|OpenGL): .")
        message(FATAL_ERROR "${_name} ${_r}: reason '${_why}'")
      endif()
    else()
      message(FATAL_ERROR "${_name} ${_r}: status ${_status}")
    endif()
  endforeach()
endforeach()
execute_process(COMMAND ${XVAL} report ${WORK}/report/results.json --extremes ${_out}
                RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "xval report exited ${_rc}:\n${_err}")
endif()
file(READ ${WORK}/report/report.html _html)
foreach(_needle "<h2 id=\"extremes\">Extremes</h2>" "extremes/specular_n1e6/heat_povray.png"
                "extremes/specular_n1e6/heat_blender.png" "extremes/specular_n1e6/heat_gl.png")
  string(FIND "${_html}" "${_needle}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "report.html lacks '${_needle}'")
  endif()
endforeach()
