# "Not expressible" is a verdict, not an error (validate/validation/compare_step.h,
# validate/validation/crosscheck.h), with stand-in POV-Ray and Blender that write the
# reference render of the scene they were given (found by its case folder):
#   - a folder mixing expressible scenes (tiny, meant_for_two), one POV-Ray
#     refuses (pov_refuses: classic Phong of shininess 1000 lit by two
#     lights whose attenuations have complex roots, a highlight POV-Ray's
#     single-precision pigments cannot keep within the tolerance) and one both external renderers refuse (wide_spp256: its
#     16 x 16 sub-pixel image would be 17600 pixels wide): the refusals
#     are recorded as not_expressible with the exporter's reason, their
#     pairs are not compared, the remaining pairs are, and the case is
#     decided on them; the summary and the report count them apart; the
#     JUnit file has them as <skipped>. wide_spp256 compares nothing: it is
#     NOT COMPARED, no pass, so the run exits 1 (validate/validation/
#     case_verdict.h);
#   - a scene's `renderers` field leaves the others out, said on stderr and
#     in results.json;
#   - --renderers runs a subset; an unknown name is an error;
#   - a POV-Ray that crashes is still an error (exit 2), and a refused
#     scene stays not expressible beside it;
#   - crosscheck of the refused scene: NOT EXPRESSIBLE, exit 0, metrics.json.
# Arguments: XVAL, SCENES (tests/cli/scenes/not_expressible), BAD (a scene
# naming an unknown renderer), XSD, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(not_expressible.cmake XVAL SCENES BAD XSD WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin ${WORK}/crash)

# The premise: POV-Ray's exporter refuses pov_refuses (if a later
# exporter expresses it, pick another refused scene for this test).
run(2 ${XVAL} export pov ${SCENES}/pov_refuses.json -o ${WORK}/export)
expect_in("${err}" "with l > 0, q > 0 and l^2 < 4 q c (or nearly equal roots) on a light with a specular highlight, among several lights")

foreach(_s tiny meant_for_two pov_refuses)
  run(0 ${XVAL} render ${SCENES}/${_s}.json -o ${WORK}/ref_${_s}.exr --precision double -q)
endforeach()
# Each stand-in writes the reference render of its case (the case folder
# is the component after out*/ in its work folder's path) where the real
# tool writes its image (POV-Ray: scene.ini's Output_File_Name; Blender: --out).
set(_scene_of "/bin/echo \"$PWD\" | /bin/sed -n 's|.*/out[^/]*/\\([^/]*\\)/.*|\\1|p'")
function(stand_in dir tool find make)
  file(WRITE ${dir}/${tool}
    "#!/bin/sh\nif [ \"$1\" = --version ]; then echo 'stand-in ${tool} 0.0'; exit 0; fi\n${find}\n${make}\n")
  file(CHMOD ${dir}/${tool} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endfunction()
stand_in(${WORK}/bin povray "out=$(/bin/sed -n 's/^Output_File_Name=//p' scene.ini)\nfor a in \"$@\"; do o=$(echo \"$a\" | /bin/sed -n 's/^+O//p'); [ -z \"$o\" ] || out=$o; done; s=$(${_scene_of})"
         "/bin/cp \"${WORK}/ref_$s.exr\" \"$out\"")
stand_in(${WORK}/bin blender "while [ $# -gt 0 ]; do if [ \"$1\" = --out ]; then out=$2; fi; shift; done; s=$(${_scene_of})"
         "/bin/cp \"${WORK}/ref_$s.exr\" \"$out\"")
stand_in(${WORK}/crash povray "" "exit 3")
file(COPY ${WORK}/bin/blender DESTINATION ${WORK}/crash)

# The three renderers the stand-ins stand for, unless the call names its own.
function(validate expect_rc path out)
  set(_subset --renderers reference,povray,blender)
  list(FIND ARGN "--renderers" _at)
  if(NOT _at EQUAL -1)
    set(_subset "")
  endif()
  validate_with_stand_ins(${expect_rc} ${path} ${ARGN} ${_subset} -o ${WORK}/${out} --jobs 2 --timeout 60 --batch 1)
  set(err "${err}" PARENT_SCOPE)
endfunction()
# The case of `scene` in results.json text `results`, into var.
function(get_case var results scene)
  string(JSON _n LENGTH "${results}" cases)
  math(EXPR _last "${_n} - 1")
  foreach(_i RANGE ${_last})
    string(JSON _c GET "${results}" cases ${_i})
    string(JSON _name GET "${_c}" scene)
    if(_name STREQUAL scene)
      set(${var} "${_c}" PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "results.json has no case ${scene}")
endfunction()

# 1. The mixed folder: exit 1, for wide_spp256 compares nothing.
validate(1 ${WORK}/bin out ${SCENES} --junit ${WORK}/junit.xml)
expect_in("${err}" "4 scenes, NOT COMPARED: 1 not compared, 3 pass (3 renders not expressible, 5 pairs not compared)")
expect_in("${err}" "meant_for_two: povray left out: the scene is meant for reference and blender only")
file(READ ${WORK}/out/results.json _r)
get_case(_c "${_r}" pov_refuses)
get_json(_why "${_c}" renders povray not_expressible)
expect_in("${_why}" "attenuation 1/(c + l d + q d^2) with l > 0, q > 0")
string(JSON _img ERROR_VARIABLE _no GET "${_c}" renders povray image)
if(NOT _no)
  message(FATAL_ERROR "pov_refuses: a not-expressible render names an image (${_img})")
endif()
get_json(_p0 "${_c}" pairs 0 pair)
get_json(_n0 "${_c}" pairs 0 not_expressible)
get_json(_p1 "${_c}" pairs 1 pair)
get_json(_pass1 "${_c}" pairs 1 pass)
get_json(_p2 "${_c}" pairs 2 pair)
get_json(_n2 "${_c}" pairs 2 not_expressible)
expect_eq("pov_refuses pair 0" "${_p0}" "reference-povray")
expect_in("${_n0}" "povray: attenuation 1/(c + l d + q d^2)")
expect_eq("pov_refuses pair 1" "${_p1}" "reference-blender")
expect_eq("pov_refuses reference-blender pass" "${_pass1}" "ON")
expect_eq("pov_refuses pair 2" "${_p2}" "povray-blender")
expect_in("${_n2}" "povray: ")
get_json(_pass "${_c}" pass)
expect_eq("pov_refuses pass" "${_pass}" "ON")
get_json(_who "${_c}" attribution)
expect_eq("pov_refuses attribution" "${_who}" "both agree; POV-Ray cannot express it")
get_case(_w "${_r}" wide_spp256)
get_json(_wp "${_w}" renders blender not_expressible)
expect_in("${_wp}" "render.spp = 256: rendered as 16 x 16 samples per pixel, the external renderer's image is 17600x128")
get_json(_who "${_w}" attribution)
expect_eq("wide_spp256 attribution" "${_who}" "nothing to compare: POV-Ray and Blender cannot express it")
get_json(_v "${_w}" verdict)
expect_eq("wide_spp256 verdict" "${_v}" "not_compared")
get_json(_pass "${_w}" pass)
expect_eq("wide_spp256 pass" "${_pass}" "OFF")
get_case(_m "${_r}" meant_for_two)
get_json(_lo "${_m}" left_out povray)
expect_in("${_lo}" "its `renderers` field")
string(JSON _np LENGTH "${_m}" pairs)
expect_eq("meant_for_two pairs" "${_np}" "1")
string(JSON _nr LENGTH "${_m}" renders)
expect_eq("meant_for_two renders" "${_nr}" "2")
get_case(_t "${_r}" tiny)
get_json(_pass "${_t}" pass)
expect_eq("tiny pass" "${_pass}" "ON")
# The report: not red, not ERROR; the summary counts it apart.
file(READ ${WORK}/out/report.html _html)
expect_in("${_html}" "<span class=\"err\">0 errors</span>, <span class=\"nexp\">1 not compared</span> (5 pairs not expressible")
expect_in("${_html}" "<summary>3 pairs: 3 not expressible</summary>")
expect_in("${_html}" "<td title=\"reference-povray\" class=\"l nexp\">not expressible</td>")
expect_in("${_html}" "nexp\">NOT COMPARED</span>")
expect_in("${_html}" "povray left out: the scene is meant for")
# JUnit: the 5 pairs as <skipped> with the reason, wide_spp256's case as
# a failure (it compared nothing), valid against the schema.
expect_valid_junit(${WORK}/junit.xml ${XSD})
file(READ ${WORK}/junit.xml _junit)
expect_in("${_junit}" "tests=\"11\" failures=\"1\" errors=\"0\" skipped=\"5\"")
expect_in("${_junit}" "<testcase classname=\"wide_spp256\" name=\"case\" time=\"0.000\">\n      <failure message=\"nothing compared (no image pair, no geometry check): nothing to compare: POV-Ray and Blender cannot express it\" type=\"not_compared\"/>")
expect_in("${_junit}" "<skipped message=\"not expressible: povray: attenuation 1/(c + l d + q d^2)")

# 2. --renderers: a subset, in registry order whatever the order given.
validate(0 ${WORK}/bin out_subset ${SCENES}/tiny.json ${SCENES}/pov_refuses.json --renderers blender,reference)
file(READ ${WORK}/out_subset/results.json _r)
get_json(_rs "${_r}" renderers)
string(REGEX REPLACE "[ \n]" "" _rs "${_rs}")
expect_eq("renderers" "${_rs}" "[\"reference\",\"blender\"]")
get_case(_c "${_r}" pov_refuses)
string(JSON _np LENGTH "${_c}" pairs)
expect_eq("pov_refuses pairs with --renderers reference,blender" "${_np}" "1")
get_json(_pass "${_c}" pass)
expect_eq("pov_refuses pass" "${_pass}" "ON")
validate(2 ${WORK}/bin out_bad ${SCENES}/tiny.json --renderers reference,pov)
expect_in("${err}" "--renderers: \"pov\": not a renderer validate runs (expected reference, povray, blender, blender-import, eevee and gl")
validate(2 ${WORK}/bin out_bad ${SCENES}/tiny.json --renderers reference)
expect_in("${err}" "--renderers: expected at least two renderers")

# 3. A scene naming an unknown renderer: an error naming the field.
validate(2 ${WORK}/bin out_bad ${BAD} --plan-only)
expect_in("${err}" "renderers[1]: unknown renderer \"pov\"")

# 4. A POV-Ray that crashes stays an error; the refusal stays a verdict.
validate(2 ${WORK}/crash out_crash ${SCENES}/tiny.json ${SCENES}/pov_refuses.json)
file(READ ${WORK}/out_crash/results.json _r)
get_case(_t "${_r}" tiny)
get_json(_e "${_t}" renders povray error)
get_case(_c "${_r}" pov_refuses)
get_json(_why "${_c}" renders povray not_expressible)
expect_in("${_why}" "attenuation 1/(c + l d + q d^2)")

# 5. crosscheck of the refused scene: a verdict, exit 0, nothing rendered.
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PATH=${WORK}/bin:/usr/bin:/bin"
                        ${XVAL} crosscheck ${SCENES}/pov_refuses.json --renderer povray -o ${WORK}/cc
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
message("crosscheck: exit ${rc}\n${out}${err}")
expect_eq("crosscheck exit" "${rc}" "0")
expect_in("${out}" "pov_refuses vs povray: NOT EXPRESSIBLE (not compared): attenuation 1/(c + l d + q d^2)")
file(READ ${WORK}/cc/metrics.json _m)
get_json(_why "${_m}" not_expressible)
expect_in("${_why}" "attenuation 1/(c + l d + q d^2)")
if(EXISTS ${WORK}/cc/povray.exr)
  message(FATAL_ERROR "crosscheck rendered a scene the renderer cannot express")
endif()
# ... and of a scene whose `renderers` does not name the renderer: an error.
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PATH=${WORK}/bin:/usr/bin:/bin"
                        ${XVAL} crosscheck ${SCENES}/meant_for_two.json --renderer povray -o ${WORK}/cc2
                RESULT_VARIABLE rc ERROR_VARIABLE err TIMEOUT 60)
expect_eq("crosscheck of a scene not meant for povray: exit" "${rc}" "2")
expect_in("${err}" "renderers: the scene is meant for reference and blender only, not povray")
