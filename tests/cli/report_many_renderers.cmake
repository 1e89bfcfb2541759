# The report of a run with many renderers (validate/report/report.h): six
# renderers, the reference and five users' renderers defined by files
# (the stand-in tests/cli/standin_renderer.sh: three hand the scene to the
# reference renderer, `kilo` dims its image, `mike` crashes), so 15 pairs:
#   - the summary table has as many columns with 15 pairs as with one (a
#     case's pairs are one cell: the worst pair, and a renderers x renderers
#     matrix), and the matrix lists the renderers in the one order (the
#     registry's: the built-in ones, then the users' by name);
#   - two runs whose --renderers and --renderer-file options come in other
#     orders give results.json and report.html the same order of renderers
#     and pairs;
#   - the renderer that failed shows its error, and no <img> of the page
#     names a file that does not exist;
#   - the provenance lists the versions of the run's renderers only (no
#     POV-Ray, Blender, EEVEE or Blender-import in a run without them);
#   - with WITH_CHROMIUM=ON (tests/cross), headless Chromium
#     opens a copy of the page with every pair matrix opened, in a 1280 px
#     wide window, and the summary table fits it (a script added to the copy measures it and
#     puts the verdict in the title).
# Arguments: XVAL, SCENE, STANDIN, WORK; WITH_CHROMIUM (optional: chromium
# must then be installed, tests/cross/report_in_chromium.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(report_many_renderers.cmake XVAL SCENE STANDIN WORK)
get_filename_component(XVAL ${XVAL} ABSOLUTE)  # the stand-in runs it from its work folder
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/def)
file(COPY ${STANDIN} DESTINATION ${WORK}/def)

set(_users zulu mike kilo bravo alpha)  # the command line's order of run 1
foreach(_name ${_users})
  set(_mode pass)
  if(_name STREQUAL "mike")
    set(_mode fail)
  elseif(_name STREQUAL "kilo")
    set(_mode dim)
  endif()
  write_standin_renderer(${WORK}/def ${_name} ${_mode})
endforeach()

# validate with the renderers and their files in the order given; the
# failed renderer makes the case an error (exit 2 or 1, not a crash).
function(validate out renderers)
  set(_files "")
  foreach(_f ${ARGN})
    list(APPEND _files --renderer-file ${WORK}/def/${_f}.json)
  endforeach()
  execute_process(COMMAND ${CMAKE_COMMAND} -E env XVAL=${XVAL}
                          ${XVAL} validate ${SCENE} -o ${out} --jobs 2 --timeout 60 --renderers ${renderers} ${_files}
                  RESULT_VARIABLE _rc ERROR_VARIABLE _err OUTPUT_VARIABLE _out TIMEOUT 240)
  message("xval validate --renderers ${renderers} (files ${ARGN}): exit ${_rc}\n${_out}\n${_err}")
  if(NOT _rc MATCHES "^[012]$" OR NOT EXISTS ${out}/results.json OR NOT EXISTS ${out}/report.html)
    message(FATAL_ERROR "xval validate exited ${_rc} without results.json and report.html")
  endif()
endfunction()

validate(${WORK}/one reference,zulu,mike,kilo,bravo,alpha zulu mike kilo bravo alpha)
list(REVERSE _users)
validate(${WORK}/two alpha,bravo,kilo,mike,zulu,reference ${_users})
validate(${WORK}/pair reference,alpha alpha)

# The order: results.json's renderers and pairs, and every renderer name on
# the page in the order it comes, are the same for both runs.
set(_order_re "(reference|alpha|bravo|kilo|mike|zulu)(-(reference|alpha|bravo|kilo|mike|zulu))?")
foreach(_run one two)
  file(READ ${WORK}/${_run}/results.json _json)
  get_json(_renderers "${_json}" renderers)
  get_json(_pairs "${_json}" cases 0 pairs)
  string(REGEX MATCHALL "\"pair\" *: *\"[a-z-]+\"" _pairs_${_run} "${_pairs}")
  string(REGEX REPLACE "[ \n]" "" _renderers_${_run} "${_renderers}")
  file(READ ${WORK}/${_run}/report.html _html_${_run})
  # Without the error text (it names the run's folder and the stand-in's
  # scratch files).
  string(REGEX REPLACE "error: [^<]*" "" _names "${_html_${_run}}")
  string(REGEX MATCHALL "${_order_re}" _names_${_run} "${_names}")
endforeach()
expect_eq("results.json renderers" "${_renderers_one}" "[\"reference\",\"alpha\",\"bravo\",\"kilo\",\"mike\",\"zulu\"]")
expect_eq("results.json renderers of run two" "${_renderers_two}" "${_renderers_one}")
list(LENGTH _pairs_one _n)
expect_eq("pairs of the case" "${_n}" "15")
expect_eq("results.json pairs of run two" "${_pairs_two}" "${_pairs_one}")
expect_eq("the renderer names of report.html, run two" "${_names_two}" "${_names_one}")

set(_html "${_html_one}")
string(FIND "${_html}" "<h2>Cases</h2>" _cases_at)
string(SUBSTRING "${_html}" 0 ${_cases_at} _summary)
expect_in("${_summary}" "<th></th><th>alpha</th><th>bravo</th><th>kilo</th><th>mike</th><th>zulu</th></tr>")
expect_in("${_summary}" "<tr><th class=\"l\">reference</th><td title=\"reference-alpha\"")
# The failing pair's cell names the first criterion it fails, with its numbers.
expect_in("${_summary}" "<td title=\"reference-kilo\" class=\"l fail\">FAIL unexplained ")
# The worst pair: an error before a failure.
expect_in("${_summary}" "class=\"l err\">ERROR<br><span class=\"pairname\">reference-mike</span>")

# The report's order is results.json's renderers: not the order in which a
# case stores its renders and pairs, nor that of the cases (failures
# first). A failing case listed first that stores its pairs backwards and
# its renders by name (CMake's JSON writes an object's members so) changes
# neither the matrix nor the order of its renders.
file(READ ${WORK}/one/results.json _json)
get_json(_case "${_json}" cases 0)
string(JSON _n LENGTH "${_case}" renders)
string(JSON _np LENGTH "${_case}" pairs)
set(_renders "{}")
set(_pairs "[]")
math(EXPR _last "${_n} - 1")
foreach(_i RANGE ${_last})
  math(EXPR _k "${_last} - ${_i}")
  string(JSON _id MEMBER "${_case}" renders ${_k})
  get_json(_v "${_case}" renders ${_id})
  string(JSON _renders SET "${_renders}" ${_id} "${_v}")
endforeach()
math(EXPR _last "${_np} - 1")
foreach(_i RANGE ${_last})
  math(EXPR _k "${_last} - ${_i}")
  get_json(_v "${_case}" pairs ${_k})
  string(JSON _pairs SET "${_pairs}" ${_i} "${_v}")
endforeach()
string(JSON _backwards SET "${_case}" renders "${_renders}")
string(JSON _backwards SET "${_backwards}" pairs "${_pairs}")
string(JSON _backwards SET "${_backwards}" scene "\"tiny-b\"")
string(JSON _backwards SET "${_backwards}" pass false)
string(JSON _json SET "${_json}" cases "[${_backwards}, ${_case}]")
file(WRITE ${WORK}/one/backwards.json "${_json}")
run(0 ${XVAL} report ${WORK}/one/backwards.json -o ${WORK}/one/backwards.html)
file(READ ${WORK}/one/backwards.html _page)
string(REGEX MATCHALL "<th></th><th>alpha</th><th>bravo</th><th>kilo</th><th>mike</th><th>zulu</th></tr>" _matrices
       "${_page}")
list(LENGTH _matrices _n)
expect_eq("pair matrices in the order of results.json renderers" "${_n}" "2")
string(FIND "${_page}" "id=\"tiny-b\"" _at)
string(SUBSTRING "${_page}" ${_at} -1 _case_b)
string(FIND "${_case_b}" "<div class=\"case\"" _end)  # the next case
string(SUBSTRING "${_case_b}" 0 ${_end} _case_b)
string(REGEX MATCHALL "<figure><img src=\"[^\"]*\" alt=\"[a-z]+\"" _figures "${_case_b}")
string(REGEX REPLACE "<figure><img src=\"[^\"]*\" alt=\"([a-z]+)\"" "\\1" _figures "${_figures}")
expect_eq("the renders of the case stored backwards" "${_figures}" "reference;alpha;bravo;kilo;zulu")

# The summary table's columns: as many with 15 pairs as with one.
function(summary_columns var html)
  string(REGEX MATCH "<h2>Summary</h2>\n<table[^>]*><tr>[^\n]*</tr>\n" _head "${html}")
  if(NOT _head)
    message(FATAL_ERROR "report.html: no summary table header")
  endif()
  string(REGEX MATCHALL "<th[ >]" _cells "${_head}")
  list(LENGTH _cells _n)
  set(${var} ${_n} PARENT_SCOPE)
endfunction()
file(READ ${WORK}/pair/report.html _html_pair)
summary_columns(_cols_15 "${_html}")
summary_columns(_cols_1 "${_html_pair}")
expect_eq("summary columns with 15 pairs (with 1 pair: ${_cols_1})" "${_cols_15}" "${_cols_1}")

# The failed renderer: its error, no image; no <img> of a missing file.
expect_in("${_html}" "<div class=\"noimage err\">error: mike (defined by ")
expect_in("${_html}" "exit code 3")
foreach(_run one two pair)
  file(READ ${WORK}/${_run}/report.html _page)
  string(REGEX MATCHALL "<img [^>]*src=\"[^\"]*\"" _imgs "${_page}")
  list(LENGTH _imgs _n)
  if(_n LESS 3)  # at least the renders and the plot
    message(FATAL_ERROR "${_run}/report.html: only ${_n} images")
  endif()
  foreach(_img ${_imgs})
    string(REGEX REPLACE ".*src=\"([^\"]*)\"" "\\1" _src "${_img}")
    if(NOT EXISTS ${WORK}/${_run}/${_src})
      message(FATAL_ERROR "${_run}/report.html: <img src=\"${_src}\">: no such file in ${WORK}/${_run}")
    endif()
  endforeach()
endforeach()

# The provenance: the run's outside renderers (the users', each with its
# version probe's answer), none it did not use.
file(READ ${WORK}/one/results.json _json)
foreach(_name alpha bravo kilo mike zulu)
  get_json(_version "${_json}" provenance ${_name})  # "unknown": the stand-in's version line does not name it
endforeach()
foreach(_unused povray blender eevee blender-import gl)
  string(JSON _v ERROR_VARIABLE _absent GET "${_json}" provenance ${_unused})
  if(NOT _absent)
    message(FATAL_ERROR "results.json: provenance.${_unused} (\"${_v}\") in a run without ${_unused}")
  endif()
  string(FIND "${_html}" "<tr><td class=\"l\">${_unused}</td>" _at)
  if(NOT _at EQUAL -1)
    message(FATAL_ERROR "report.html: the provenance table lists ${_unused}, which the run did not use")
  endif()
endforeach()

if(NOT WITH_CHROMIUM)
  return()
endif()
# Chromium: every matrix opened, does the summary table fit 1280 px?
string(REPLACE "</body>" "<script>
window.addEventListener('load', function () {
  document.querySelectorAll('details').forEach(function (d) { d.open = true; });
  var h = Array.prototype.find.call(document.querySelectorAll('h2'),
                                    function (e) { return e.textContent === 'Summary'; });
  var t = h && h.nextElementSibling;  // the summary table
  var right = t ? Math.ceil(t.getBoundingClientRect().right) : -1;
  document.title = (t && right <= window.innerWidth ? 'summary fits' : 'summary overflows') +
                   ': right ' + right + ' of ' + window.innerWidth + ' px';
});
</script></body>" _measured "${_html}")
file(WRITE ${WORK}/one/report_measured.html "${_measured}")
set(REPORT ${WORK}/one/report_measured.html)
set(SHOT ${WORK}/one/summary.png)
set(TITLE "summary fits")
set(WINDOW 1280,900)
include(${CMAKE_CURRENT_LIST_DIR}/../cross/report_in_chromium.cmake)
