# `xval tradeoff` end to end on the Table 2 scene (textured YIQ knot,
# Phong shading, bilinear brick texture) at a small resolution, then
# `xval report` on a copy of the published results.json given the tradeoff
# folder (--tradeoff). Checks:
#   - exit 0, and the outputs exist (tradeoff.json, .tsv, .md, pareto.png);
#   - tradeoff.json has its fields, on every configuration;
#   - the converged configuration's own error is 0 (max and RMSE): it is
#     rendered again and compared with the reference, so this checks that
#     rendering is deterministic and that the error is measured between the
#     right images;
#   - the error (RMSE and mean CIEDE2000) of 1 spp is larger than that of
#     16 spp. Why this must hold here: the reference is the pixel's box
#     average (a finer 8 x 8 stratified grid over a finer mesh); on this
#     knot the brick texture is minified (several texels and mortar lines
#     per pixel), and Phong shading puts the highlight and the silhouettes
#     inside pixels, so the colour varies within most covered pixels. One
#     sample at the centre misses that variation by its full size, while
#     the 4 x 4 grid estimates the same average from 16 strata, each error
#     bounded by the variation within a quarter-pixel; both use the same
#     mesh, so the tessellation's share of the error is the same in both.
#     (On an untextured, flat-shaded plane both would be 0 and the check
#     meaningless, hence this scene.) Measured at 96 x 96: RMSE 4337 vs
#     596 (1/65535);
#   - the report includes the trade-off section and the plot.
# Arguments: XVAL, SCENE, RESULTS (a results.json), WORK.
foreach(_v XVAL SCENE RESULTS WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "tradeoff.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/report)
set(_out ${WORK}/report/tradeoff)
execute_process(
  COMMAND ${XVAL} tradeoff ${SCENE} -o ${_out} --width 96 --height 96 --frames 2 --max-seconds 1
  RESULT_VARIABLE _rc ERROR_VARIABLE _err OUTPUT_VARIABLE _stdout)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "xval tradeoff exited ${_rc}:\n${_err}")
endif()
foreach(_progress "[reference]" "[check 1/2]" "[1/16] base" "Pareto-optimal")
  string(FIND "${_err}" "${_progress}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "no progress line '${_progress}' on stderr:\n${_err}")
  endif()
endforeach()
foreach(_f tradeoff.json tradeoff.tsv tradeoff.md pareto.png pareto.gp pareto.dat)
  if(NOT EXISTS ${_out}/${_f})
    message(FATAL_ERROR "${_out}/${_f} was not written")
  endif()
endforeach()

file(READ ${_out}/tradeoff.json _j)
string(JSON _format GET "${_j}" format)
if(NOT _format STREQUAL "xval-tradeoff/1")
  message(FATAL_ERROR "format: ${_format}")
endif()
foreach(_field scene width height command date_utc machine timing error_definition pareto_metric
               pareto_error_tolerance reference configs pareto_front total_seconds)
  string(JSON _v ERROR_VARIABLE _e GET "${_j}" ${_field})
  if(_e)
    message(FATAL_ERROR "tradeoff.json: ${_field}: ${_e}")
  endif()
endforeach()
string(JSON _w GET "${_j}" width)
if(NOT _w EQUAL 96)
  message(FATAL_ERROR "width: expected 96 (--width), got ${_w}")
endif()
string(JSON _nconv LENGTH "${_j}" reference convergence)
if(NOT _nconv EQUAL 2)
  message(FATAL_ERROR "reference.convergence: expected 2 checks, got ${_nconv}")
endif()
string(JSON _n LENGTH "${_j}" configs)
if(NOT _n EQUAL 17)
  message(FATAL_ERROR "configs: expected 17 rows, got ${_n}")
endif()
math(EXPR _last "${_n} - 1")
foreach(_i RANGE ${_last})
  string(JSON _id GET "${_j}" configs ${_i} id)
  foreach(_k group frame_median_s frame_min_s frame_max_s frames setup_s pareto pareto_error
             "knobs;spp" "knobs;tessellation_factor" "knobs;segments" "knobs;triangles" "knobs;precision"
             "knobs;shading" "knobs;texture_filter" "error;max_16bit" "error;p999_16bit" "error;rmse_16bit"
             "error;ciede2000_mean" "error;ciede2000_max" "error;pixels")
    string(JSON _v ERROR_VARIABLE _e GET "${_j}" configs ${_i} ${_k})
    if(_e)
      message(FATAL_ERROR "tradeoff.json: configs[${_i}] (${_id}): ${_k}: ${_e}")
    endif()
  endforeach()
  string(MAKE_C_IDENTIFIER "${_id}" _cid)  # spp=16 -> spp_16
  string(JSON _rmse_${_cid} GET "${_j}" configs ${_i} error rmse_16bit)
  string(JSON _max_${_cid} GET "${_j}" configs ${_i} error max_16bit)
  string(JSON _de_${_cid} GET "${_j}" configs ${_i} error ciede2000_mean)
  string(JSON _spp_${_cid} GET "${_j}" configs ${_i} knobs spp)
endforeach()

# The converged configuration against its own reference: exactly 0.
if(NOT _rmse_converged EQUAL 0 OR NOT _max_converged EQUAL 0)
  message(FATAL_ERROR "converged: error against its own reference is not 0 (max ${_max_converged}, RMSE ${_rmse_converged})")
endif()
# 1 spp (the base: the scene's own spp) against 16 spp.
if(NOT _spp_base EQUAL 1 OR NOT _spp_spp_16 EQUAL 16)
  message(FATAL_ERROR "expected base at 1 spp and spp=16 at 16, got ${_spp_base} and ${_spp_spp_16}")
endif()
# CMake compares floats as numbers with LESS/GREATER.
if(NOT _rmse_base GREATER _rmse_spp_16)
  message(FATAL_ERROR "RMSE at 1 spp (${_rmse_base}) is not larger than at 16 spp (${_rmse_spp_16})")
endif()
if(NOT _de_base GREATER _de_spp_16)
  message(FATAL_ERROR "CIEDE2000 at 1 spp (${_de_base}) is not larger than at 16 spp (${_de_spp_16})")
endif()
message("converged error 0; RMSE 1 spp ${_rmse_base} > 16 spp ${_rmse_spp_16}; CIEDE2000 ${_de_base} > ${_de_spp_16}")

# The report on a copy of a results.json, given the tradeoff folder.
file(COPY_FILE ${RESULTS} ${WORK}/report/results.json)
# A copy of a results.json elsewhere: the section folders it records
# (relative to it) are not copied, and `xval report` refuses a named folder
# that is missing, so the copy drops them and names only this test's one.
file(READ ${WORK}/report/results.json _rj)
string(JSON _rj_stripped ERROR_VARIABLE _rj_err REMOVE "${_rj}" sections)
if(NOT _rj_err)
  file(WRITE ${WORK}/report/results.json "${_rj_stripped}")
endif()
execute_process(COMMAND ${XVAL} report ${WORK}/report/results.json --tradeoff ${_out}
  RESULT_VARIABLE _rc ERROR_VARIABLE _err)
if(NOT _rc EQUAL 0)
  message(FATAL_ERROR "xval report exited ${_rc}:\n${_err}")
endif()
file(READ ${WORK}/report/report.html _html)
foreach(_s "Speed against accuracy" "src=\"tradeoff/pareto.png\"" "corner:accurate" "check:spp=256")
  string(FIND "${_html}" "${_s}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "report.html has no '${_s}'")
  endif()
endforeach()
