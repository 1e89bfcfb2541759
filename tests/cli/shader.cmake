# The shader renderer (docs/shaders.md) on the paper's listing as printed
# (reference/shaders) and on broken copies of it, one CASE per test:
#   listing_passes            the listing, crosscheck against the reference: PASS
#   missing_saturate_fails    Diffuse without its inner saturate: FAIL (exit 1)
#   reflection_sign_fails     R = -normalize(...): FAIL (exit 1)
#   light_unnormalised_fails  LightVector = LightPos - PosWorld, not normalised (both copies of the
#                             duplicated line, so the tool's one edit still applies): FAIL (exit 1)
#   yiq_rows_swapped_fails    RGBtoYIQ with its I and Q rows swapped: FAIL (exit 1)
#   unbound_uniform_error     no "uniforms" mapping for AmbientValue: an error naming it (exit 2)
#   compile_error             a call glslang refuses: an error naming the file's line (exit 2)
#   infinite_loop_times_out   a loop that never ends: killed at --timeout, an error (exit 2).
#                             llvmpipe ends any loop after 65536 turns (measured: an endless
#                             loop counting its turns returned 65536), so the loop's body is
#                             made costly enough (64 sin a turn, 18 s here) to outlast --timeout 4
#   two_lights_not_expressible a second point light: NOT EXPRESSIBLE with the reason
#   source_outside_refused    "source": "../..." : an error naming the field (exit 2)
#   phong_example_passes      docs/examples/shaders/phong.json (a user's effect with its own uniform
#                             names mapped) against the reference on a classic-Phong scene: PASS
#   glsl_example_passes       docs/examples/shaders/phong330.json (GLSL 3.30, names mapped) likewise: PASS
#   glsl_unmapped_uniform_error that definition without u_ka's mapping: an error naming u_ka (exit 2)
#   validate_expresses_or_refuses  validate on three reference scenes (REFERENCE_SCENES), the listing's
#                             definition given to --renderer-file (docs/shaders.md: the way a shader
#                             joins a run): fig1_yiq_front_listing compared (reference-paper-listing
#                             pass); fig1_yiq_specular (kd 0) and fig1_yiq_front (the normal
#                             re-normalised, which the definition declares the listing does not do)
#                             refused with their reasons, printed and in results.json; every case
#                             passes on the pairs it compares (exit 0)
#   golden_update_and_check   golden update of the listing's images of a set (SCENE), golden check
#                             and validate against golden-paper-listing pass; a scene the listing
#                             cannot express is refused by golden-paper-listing with the listing's
#                             reason (not an error hinting at a golden update that would refuse it);
#                             a broken listing (missing saturate) then fails golden check (exit 1)
#   bench_beside_gl           bench times gl and the listing in one process (gl's EGL display made
#                             first must not reach the shader's draw: a forked draw hung on it)
# Each broken copy is made from the listing by string(REPLACE) here, and the
# script fails if the text to replace is not found (the mutation must bite).
# Arguments: XVAL, LISTING (the .fx), DEFINITION (its .json), SCENE (a small
# scene the listing can express), PHONG (docs/examples/shaders/phong.json),
# REFERENCE_SCENES (reference/scenes), CASE, WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(shader.cmake XVAL LISTING DEFINITION SCENE PHONG REFERENCE_SCENES CASE WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/shader)
file(READ ${LISTING} listing)
file(READ ${DEFINITION} definition)

# OUT_VAR = TEXT with FROM replaced by TO; fails, naming WHAT, if FROM is
# not found (the change must bite).
function(replaced out_var what text from to)
  string(FIND "${text}" "${from}" _at)
  if(_at EQUAL -1)
    message(FATAL_ERROR "${what} has no \"${from}\" to replace")
  endif()
  string(REPLACE "${from}" "${to}" text "${text}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

# WORK/shader/broken.fx: the listing with FROM replaced by TO (each pair
# FROM TO of the arguments, in order); broken.json its definition.
function(broken)
  set(_text "${listing}")
  set(_i 0)
  while(_i LESS ARGC)  # ARGVn, not ${ARGV}: the texts hold semicolons
    math(EXPR _j "${_i} + 1")
    replaced(_text "the listing" "${_text}" "${ARGV${_i}}" "${ARGV${_j}}")
    math(EXPR _i "${_i} + 2")
  endwhile()
  file(WRITE ${WORK}/shader/broken.fx "${_text}")
  string(REPLACE "kotsarenko2012_table1.fx" "broken.fx" _def "${definition}")
  file(WRITE ${WORK}/shader/broken.json "${_def}")
endfunction()

# WORK/phong.json: SCENE with the classic Phong model (paper variant) and
# the re-normalised normal the Phong examples compute.
function(phong_scene)
  file(READ ${SCENE} _scene)
  replaced(_phong "the scene" "${_scene}" "\"type\": \"yiq_luma\"" "\"type\": \"classic_phong\", \"variant\": \"paper\"")
  replaced(_phong "the scene" "${_phong}" "\"normalize_normal\": false" "\"normalize_normal\": true")
  file(WRITE ${WORK}/phong.json "${_phong}")
endfunction()

set(def ${WORK}/shader/broken.json)
set(crosscheck ${XVAL} crosscheck ${SCENE} --renderer paper-listing --renderer-file ${def} -o ${WORK}/out)

if(CASE STREQUAL "listing_passes")
  broken("float4x4 World " "float4x4 World ")  # the listing unchanged
  run(0 ${crosscheck})
  expect_in("${out}${err}" "vs paper-listing: PASS")
elseif(CASE STREQUAL "missing_saturate_fails")
  broken("saturate(saturate(dot(LightVector, \nNormalWorld)) +" "saturate(dot(LightVector, \nNormalWorld) +")
  run(1 ${crosscheck})
  expect_in("${out}${err}" "vs paper-listing: FAIL")
elseif(CASE STREQUAL "reflection_sign_fails")
  broken("float3 Reflection = normalize(" "float3 Reflection = -normalize(")
  run(1 ${crosscheck})
  expect_in("${out}${err}" "vs paper-listing: FAIL")
elseif(CASE STREQUAL "light_unnormalised_fails")
  broken("float3 LightVector = normalize(LightPos - PosWorld);" "float3 LightVector = LightPos - PosWorld;")
  run(1 ${crosscheck})
  expect_in("${out}${err}" "vs paper-listing: FAIL")
elseif(CASE STREQUAL "yiq_rows_swapped_fails")
  # OutCol.x (I) takes Q's row and OutCol.z (Q) I's: a placeholder keeps the two replacements apart.
  broken("OutCol.x = 0.59597799f" "OutCol.SWAP = 0.59597799f"
         "OutCol.z = 0.21147017f" "OutCol.x = 0.21147017f"
         "OutCol.SWAP = 0.59597799f" "OutCol.z = 0.59597799f")
  run(1 ${crosscheck})
  expect_in("${out}${err}" "vs paper-listing: FAIL")
elseif(CASE STREQUAL "unbound_uniform_error")
  broken("float4x4 World " "float4x4 World ")
  string(REPLACE "\"uniforms\": {\"AmbientValue\": \"ambient_luma\"}," "" _def "${definition}")
  string(REPLACE "kotsarenko2012_table1.fx" "broken.fx" _def "${_def}")
  file(WRITE ${def} "${_def}")
  run(2 ${crosscheck})
  expect_in("${err}" "the uniform \"AmbientValue\" has no semantic")
  expect_in("${err}" "nothing binds it")
elseif(CASE STREQUAL "compile_error")
  broken("float3 WorkCol = RGBtoYIQ(TexCol);" "float3 WorkCol = RGBtoYIQ(TexCol, TexAt);")
  run(2 ${crosscheck})
  expect_in("${err}" "glslangValidator")
  expect_in("${err}" "${WORK}/shader/broken.fx:106:")  # the user's file and line, not a temporary copy's
elseif(CASE STREQUAL "infinite_loop_times_out")
  broken("float3 WorkCol = RGBtoYIQ(TexCol);"
         "float k = TexCol.g; for (;;) { for (int j = 0; j < 64; ++j) k = sin(k * 1.0001f + 0.5f); if (TexCol.r < -1.0f) break; }\n  TexCol.g = k; float3 WorkCol = RGBtoYIQ(TexCol);")
  run(2 ${crosscheck} --timeout 4)
  expect_in("${err}" "timed out")
elseif(CASE STREQUAL "two_lights_not_expressible")
  broken("float4x4 World " "float4x4 World ")
  file(READ ${SCENE} _scene)
  string(REPLACE "{\n      \"type\": \"ambient\"" "{\"type\": \"point\", \"position\": [1, 1, 3]},\n    {\n      \"type\": \"ambient\"" _two "${_scene}")
  if(_two STREQUAL _scene)
    message(FATAL_ERROR "the scene's ambient light was not found to add a point light before")
  endif()
  file(WRITE ${WORK}/two_lights.json "${_two}")
  run(0 ${XVAL} crosscheck ${WORK}/two_lights.json --renderer paper-listing --renderer-file ${def} -o ${WORK}/out)
  expect_in("${out}${err}" "NOT EXPRESSIBLE")
  expect_in("${out}${err}" "one point light: the scene has 2")
elseif(CASE STREQUAL "source_outside_refused")
  broken("float4x4 World " "float4x4 World ")
  file(MAKE_DIRECTORY ${WORK}/shader/inner)
  string(REPLACE "kotsarenko2012_table1.fx" "../broken.fx" _def "${definition}")
  file(WRITE ${WORK}/shader/inner/outside.json "${_def}")
  run(2 ${XVAL} crosscheck ${SCENE} --renderer paper-listing --renderer-file ${WORK}/shader/inner/outside.json -o ${WORK}/out)
  expect_in("${err}" "source")
  expect_in("${err}" "'..' is refused")
elseif(CASE STREQUAL "phong_example_passes")
  phong_scene()
  run(0 ${XVAL} crosscheck ${WORK}/phong.json --renderer phong-fx --renderer-file ${PHONG} -o ${WORK}/out)
  expect_in("${out}${err}" "vs phong-fx: PASS")
elseif(CASE STREQUAL "glsl_example_passes" OR CASE STREQUAL "glsl_unmapped_uniform_error")
  phong_scene()
  get_filename_component(_examples ${PHONG} DIRECTORY)
  foreach(_f phong330.frag phong330.vert phong330.json)
    file(COPY ${_examples}/${_f} DESTINATION ${WORK}/glsl)
  endforeach()
  if(CASE STREQUAL "glsl_unmapped_uniform_error")
    file(READ ${WORK}/glsl/phong330.json _def)
    string(REPLACE "\"u_ka\": \"ka\"," "" _unmapped "${_def}")
    if(_unmapped STREQUAL _def)
      message(FATAL_ERROR "phong330.json has no u_ka mapping to remove")
    endif()
    file(WRITE ${WORK}/glsl/phong330.json "${_unmapped}")
    run(2 ${XVAL} crosscheck ${WORK}/phong.json --renderer phong-glsl --renderer-file ${WORK}/glsl/phong330.json -o ${WORK}/out)
    expect_in("${err}" "uniform \"u_ka\" is bound by nothing")
  else()
    run(0 ${XVAL} crosscheck ${WORK}/phong.json --renderer phong-glsl --renderer-file ${WORK}/glsl/phong330.json -o ${WORK}/out)
    expect_in("${out}${err}" "vs phong-glsl: PASS")
  endif()
elseif(CASE STREQUAL "validate_expresses_or_refuses")
  run(0 ${XVAL} validate ${REFERENCE_SCENES}/fig1_yiq_front_listing.json ${REFERENCE_SCENES}/fig1_yiq_specular.json
      ${REFERENCE_SCENES}/fig1_yiq_front.json --renderer-file ${DEFINITION} --renderers reference,gl,paper-listing -o ${WORK}/validation --jobs 2)
  if(NOT "${out}${err}" MATCHES "fig1_yiq_specular +paper-listing not expressible")
    message(FATAL_ERROR "does not say that paper-listing cannot express fig1_yiq_specular")
  endif()
  expect_in("${out}${err}" "paper-listing hard-codes kd = 1: the scene's material has 0.0")
  expect_in("${out}${err}" "paper-listing uses the interpolated normal as it is, not re-normalised")
  expect_in("${out}${err}" "3 scenes, all pass")
  file(READ ${WORK}/validation/results.json _results)
  # case scene -> the verdict of its reference-paper-listing pair (and its reason when refused)
  string(JSON _cases LENGTH "${_results}" cases)
  set(_seen "")
  math(EXPR _last_case "${_cases} - 1")
  foreach(_c RANGE ${_last_case})
    string(JSON _scene GET "${_results}" cases ${_c} scene)
    string(JSON _verdict GET "${_results}" cases ${_c} verdict)
    expect_eq("${_scene}'s verdict" "${_verdict}" "pass")
    string(JSON _pairs LENGTH "${_results}" cases ${_c} pairs)
    math(EXPR _last_pair "${_pairs} - 1")
    foreach(_p RANGE ${_last_pair})
      string(JSON _pair GET "${_results}" cases ${_c} pairs ${_p} pair)
      if(_pair STREQUAL "reference-paper-listing")
        string(JSON _pv GET "${_results}" cases ${_c} pairs ${_p} verdict)
        list(APPEND _seen "${_scene}=${_pv}")
        if(_scene STREQUAL "fig1_yiq_specular")
          string(JSON _why GET "${_results}" cases ${_c} pairs ${_p} not_expressible)
          expect_in("${_why}" "hard-codes kd = 1")
        elseif(_scene STREQUAL "fig1_yiq_front")
          string(JSON _why GET "${_results}" cases ${_c} pairs ${_p} not_expressible)
          expect_in("${_why}" "the scene asks for normalize_normal true")
        endif()
      endif()
    endforeach()
  endforeach()
  list(SORT _seen)
  expect_eq("reference-paper-listing verdicts" "${_seen}"
            "fig1_yiq_front=not_expressible;fig1_yiq_front_listing=pass;fig1_yiq_specular=not_expressible")
elseif(CASE STREQUAL "golden_update_and_check")
  broken("float4x4 World " "float4x4 World ")
  file(MAKE_DIRECTORY ${WORK}/set/scenes)
  file(COPY ${SCENE} DESTINATION ${WORK}/set/scenes)
  set(_with --renderer paper-listing --renderer-file ${def})
  run(0 ${XVAL} golden update ${WORK}/set/scenes ${_with})
  if(NOT EXISTS ${WORK}/set/golden/paper-listing/shader_knot.exr)
    message(FATAL_ERROR "golden update stored no ${WORK}/set/golden/paper-listing/shader_knot.exr")
  endif()
  run(0 ${XVAL} golden check ${WORK}/set/scenes ${_with})
  expect_in("${out}${err}" "1 of 1 scenes match their golden images of paper-listing")
  run(0 ${XVAL} validate ${WORK}/set/scenes --renderers reference,golden-paper-listing --renderer-file ${def}
      -o ${WORK}/validation --jobs 2)
  expect_in("${out}${err}" "1 scene, all pass")
  # A scene the listing cannot express (the normal re-normalised) has no image in its set: the golden set
  # refuses it with the listing's reason, rather than hint at a golden update that would refuse it.
  file(READ ${SCENE} _scene)
  replaced(_normalised "the scene" "${_scene}" "\"normalize_normal\": false" "\"normalize_normal\": true")
  replaced(_normalised "the scene" "${_normalised}" "\"name\": \"shader_knot\"" "\"name\": \"shader_knot_normalised\"")
  file(WRITE ${WORK}/set/scenes/shader_knot_normalised.json "${_normalised}")
  run(0 ${XVAL} validate ${WORK}/set/scenes --renderers reference,gl,golden-paper-listing --renderer-file ${def}
      -o ${WORK}/validation_refused --jobs 2)
  expect_in("${out}${err}" "paper-listing cannot express the scene, so its golden set has no image of it: paper-listing uses the interpolated normal as it is")
  expect_in("${out}${err}" "2 scenes, all pass")
  file(REMOVE ${WORK}/set/scenes/shader_knot_normalised.json)
  broken("saturate(saturate(dot(LightVector, \nNormalWorld)) +" "saturate(dot(LightVector, \nNormalWorld) +")
  run(1 ${XVAL} golden check ${WORK}/set/scenes ${_with})
  expect_in("${out}${err}" "outside the tolerance")
  expect_in("${out}${err}" "0 of 1 scenes match their golden images of paper-listing")
elseif(CASE STREQUAL "bench_beside_gl")
  broken("float4x4 World " "float4x4 World ")
  run(0 ${XVAL} bench ${SCENE} --renderers gl,paper-listing --renderer-file ${def} --frames 2 --runs 1)
  expect_in("${out}${err}" "paper-listing      frame")
else()
  message(FATAL_ERROR "unknown CASE ${CASE}")
endif()
