# `xval extremes` end to end without external renderers, at 48 x 48 (a few
# seconds), then `xval report` on a copy of a results.json given the
# extremes folder (--extremes). Checks:
#   - exit 0: the reference renderer has no NaN/Inf in any case, in either
#     precision, final or raw channels (the command exits 1 otherwise);
#   - a progress line per case on stderr;
#   - the outputs: extremes.json (format, totals, per case the scene file,
#     both NaN/Inf counts = 0, float-vs-double metrics and map), extremes.md,
#     heat_scale.png, the scene files and the palette, previews and maps;
#   - a written scene renders with `xval render` (the documented rerun);
#   - the report includes the Extremes section with every case;
#   - --only with an unknown case is an error (exit 2) listing the cases.
# Arguments: XVAL, RESULTS (a results.json), WORK.
foreach(_v XVAL RESULTS WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "extremes.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/report)
set(_out ${WORK}/report/extremes)
execute_process(COMMAND ${XVAL} extremes -o ${_out} --no-external --size 48
                RESULT_VARIABLE _rc ERROR_VARIABLE _err OUTPUT_VARIABLE _stdout)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "xval extremes exited ${_rc} (1: NaN/Inf in the reference renderer):\n${_err}")
endif()
foreach(_progress "cases, 48x48" "specular_n1e6" "offset_1e6" "reference renderer NaN/Inf pixels: 0")
  string(FIND "${_err}" "${_progress}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "no '${_progress}' on stderr:\n${_err}")
  endif()
endforeach()
foreach(_f extremes.json extremes.md heat_scale.png scenes/palette.png scenes/specular_n1e6.json
           specular_n1e6/double.png specular_n1e6/heat_float.png specular_n1e6/double.exr
           specular_n1e6/float.exr)
  if(NOT EXISTS ${_out}/${_f})
    message(FATAL_ERROR "${_out}/${_f} was not written")
  endif()
endforeach()

file(READ ${_out}/extremes.json _j)
string(JSON _format GET "${_j}" format)
if(NOT _format STREQUAL "xval-extremes/1")
  message(FATAL_ERROR "format: ${_format}")
endif()
string(JSON _bad GET "${_j}" totals reference_nonfinite_pixels)
if(NOT _bad EQUAL 0)
  message(FATAL_ERROR "totals.reference_nonfinite_pixels: ${_bad}")
endif()
string(JSON _n LENGTH "${_j}" cases)
if(_n LESS 25)
  message(FATAL_ERROR "cases: expected the whole matrix (>= 25), got ${_n}")
endif()
math(EXPR _last "${_n} - 1")
foreach(_i RANGE ${_last})
  string(JSON _name GET "${_j}" cases ${_i} name)
  string(JSON _scene GET "${_j}" cases ${_i} scene)
  if(NOT EXISTS ${_out}/${_scene})
    message(FATAL_ERROR "${_name}: scene file ${_scene} missing")
  endif()
  foreach(_p double float)
    foreach(_ch final raw)
      string(JSON _c GET "${_j}" cases ${_i} reference ${_p} nonfinite ${_ch})
      if(NOT _c EQUAL 0)
        message(FATAL_ERROR "${_name}: ${_p} ${_ch}: ${_c} pixels with NaN/Inf")
      endif()
    endforeach()
  endforeach()
  foreach(_k max_abs_16bit p999_abs_16bit mask_disagree map)
    string(JSON _v ERROR_VARIABLE _e GET "${_j}" cases ${_i} float_vs_double ${_k})
    if(_e)
      message(FATAL_ERROR "${_name}: float_vs_double.${_k}: ${_e}")
    endif()
  endforeach()
  string(JSON _map GET "${_j}" cases ${_i} float_vs_double map)
  if(NOT EXISTS ${_out}/${_map})
    message(FATAL_ERROR "${_name}: map ${_map} missing")
  endif()
endforeach()

# The documented rerun of one case.
execute_process(COMMAND ${XVAL} render ${_out}/scenes/offset_1e6.json -o ${WORK}/rerun.exr
                        --precision float -q
                RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0 OR NOT EXISTS ${WORK}/rerun.exr)
  message(FATAL_ERROR "xval render of a written scene failed (${_rc}):\n${_err}")
endif()

# The report's section.
file(COPY ${RESULTS} DESTINATION ${WORK}/report)
get_filename_component(_results_name ${RESULTS} NAME)
# A copy of a results.json elsewhere: the section folders it records
# (relative to it) are not copied, and `xval report` refuses a named folder
# that is missing, so the copy drops them and names only this test's one.
file(READ ${WORK}/report/${_results_name} _rj)
string(JSON _rj_stripped ERROR_VARIABLE _rj_err REMOVE "${_rj}" sections)
if(NOT _rj_err)
  file(WRITE ${WORK}/report/${_results_name} "${_rj_stripped}")
endif()
execute_process(COMMAND ${XVAL} report ${WORK}/report/${_results_name} --extremes ${_out}
                RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "xval report exited ${_rc}:\n${_err}")
endif()
file(READ ${WORK}/report/report.html _html)
foreach(_needle "<h2 id=\"extremes\">Extremes</h2>" "extremes/specular_n1e6/heat_float.png"
                "id=\"x-spot_cone_edge\"" "extremes/heat_scale.png")
  string(FIND "${_html}" "${_needle}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "report.html lacks '${_needle}'")
  endif()
endforeach()

# An unknown case name.
execute_process(COMMAND ${XVAL} extremes -o ${WORK}/bad --only no_such_case --no-external
                RESULT_VARIABLE _rc ERROR_VARIABLE _err)
string(FIND "${_err}" "no case named no_such_case; the cases are: specular_n0" _at)
if(NOT _rc EQUAL 2 OR _at EQUAL -1)
  message(FATAL_ERROR "--only no_such_case: expected exit 2 and the list of cases, got ${_rc}:\n${_err}")
endif()
