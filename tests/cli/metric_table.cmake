# The metric table (renderer/image/metric_table.h) in every output that
# reports a pair: `xval validate` with a renderer that disagrees (the
# stand-in's `dim`: half the reference's colour) writes, per compared pair,
# metrics.values with every id of the table (FLIP among them, > 0 here);
# the report has a column per entry (its label) and the JUnit file a
# property per entry; `xval compare --json` has the same values and its
# text a "metrics:" line; `xval tradeoff --help` offers the table's errors
# (FLIP among them, SSIM not: higher is better) as --metric.
# Arguments: XVAL, SCENE (tests/cli/scenes/tiny.json), STANDIN
# (standin_renderer.sh), WORK.
foreach(_v XVAL SCENE STANDIN WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "metric_table.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

set(_ids max p999 rmse psnr ssim ciede2000 ciede2000_max yiq yiq_max flip flip_p99)
set(_labels "max error" "p99.9 error" "RMSE" "PSNR" "SSIM" "mean CIEDE2000" "max CIEDE2000" "mean YIQ delta"
            "max YIQ delta" "mean FLIP" "p99 FLIP")

file(WRITE ${WORK}/def/standin.json "{\"format\": \"xval-renderer/1\", \"name\": \"standin\", \"input\": \"scene\",
 \"command\": [\"./standin_renderer.sh\", \"dim\", \"{scene}\", \"{output}\", \"{width}\", \"{height}\"],
 \"version_command\": [\"./standin_renderer.sh\", \"--version\"]}\n")
run_xval(1 _o validate ${SCENE} --renderers reference,standin --renderer-file ${WORK}/def/standin.json
         -o ${WORK}/run --junit ${WORK}/run.xml)
file(READ ${WORK}/run/results.json _r)
string(JSON _pair GET "${_r}" cases 0 pairs 0 pair)
expect("${_pair}" "^reference-standin$" "the compared pair")
foreach(_id ${_ids})
  string(JSON _v ERROR_VARIABLE _e GET "${_r}" cases 0 pairs 0 metrics values ${_id})
  if(_e)
    message(FATAL_ERROR "results.json: cases[0].pairs[0].metrics.values has no \"${_id}\": ${_e}")
  endif()
endforeach()
string(JSON _flip GET "${_r}" cases 0 pairs 0 metrics values flip)
if(NOT _flip GREATER 0)
  message(FATAL_ERROR "mean FLIP of a render against its half-bright copy is ${_flip}, expected > 0")
endif()

file(READ ${WORK}/run/report.html _html)
expect("${_html}" "<table class=\"metrics\">" "the report's metrics table")
foreach(_label ${_labels})
  expect("${_html}" ">${_label}" "the report's column for ${_label}")
endforeach()

file(READ ${WORK}/run.xml _x)
foreach(_id ${_ids})
  expect("${_x}" "<property name=\"metric.${_id}\" value=\"" "the JUnit property of ${_id}")
endforeach()

run_xval(1 _c compare ${WORK}/run/tiny/reference.exr ${WORK}/run/tiny/standin.exr --json)
string(JSON _cflip GET "${_c}" values flip)
if(NOT _cflip GREATER 0)
  message(FATAL_ERROR "xval compare --json: values.flip is ${_cflip}, expected > 0")
endif()
run_xval(1 _t compare ${WORK}/run/tiny/reference.exr ${WORK}/run/tiny/standin.exr)
expect("${_t}" "metrics: max error [^\n]*mean FLIP [0-9]" "xval compare's metrics line")

run_xval(0 _h tradeoff --help)
expect("${_h}" "--metric TEXT:{max,p999,rmse,ciede2000,ciede2000_max,yiq,yiq_max,flip,flip_p99}"
       "xval tradeoff's axes")
