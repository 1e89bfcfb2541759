# Scene strings made of shell, SDL and Python (hostile.json: the name and
# the texture path) go through `xval validate` with stand-in povray and
# blender that record what they were started with. Checks:
#   - nothing the strings ask for happens (no PWNED_* file anywhere);
#   - the tools' command lines are fixed: povray gets `scene.ini`, blender
#     its fixed flags, the script and two paths inside the output folder;
#   - the generated files (scene.pov, scene.ini, scene.gltf) carry none of
#     the strings (the .pov's first comment line carries the name with
#     every character that means something in SDL replaced; the glTF
#     carries the scene description as one JSON string, which the Blender
#     script reads with json.loads: it must give the name back exactly);
#   - the case's folder is a direct child of the output folder;
#   - a hostile output folder name (-o with $(...)) runs nothing either:
#     the report's gnuplot call is the one place xval goes through /bin/sh.
# Arguments: XVAL, SCENE (hostile.json), TEXTURE (a PNG), WORK.
foreach(_v XVAL SCENE TEXTURE WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "injection.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin ${WORK}/scene ${WORK}/cwd)
file(COPY ${SCENE} DESTINATION ${WORK}/scene)
get_filename_component(_scene_name ${SCENE} NAME)
# The texture file under the hostile name the scene gives.
set(_tex "t $(touch PWNED_TEX) `touch PWNED_TEX2`; #declare X = 1; } '\"\"\".png")
file(COPY_FILE ${TEXTURE} "${WORK}/scene/${_tex}")

# Each argument is recorded in its own file (arguments may hold newlines).
foreach(_tool povray blender)
  file(WRITE ${WORK}/bin/${_tool} "#!/bin/sh
if [ \"$1\" = --version ]; then echo 'stand-in ${_tool} 0.0'; exit 0; fi
d='${WORK}/${_tool}.args'
/bin/mkdir \"$d\"
echo $# > \"$d/argc\"
i=0
for a in \"$@\"; do i=$((i + 1)); printf '%s' \"$a\" > \"$d/$i\"; done
echo 'stand-in ${_tool}: recorded its arguments'
exit 3
")
  file(CHMOD ${WORK}/bin/${_tool} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
endforeach()
find_program(_gnuplot gnuplot)
if(_gnuplot)
  file(CREATE_LINK ${_gnuplot} ${WORK}/bin/gnuplot SYMBOLIC)
endif()

set(_out "${WORK}/out $(touch PWNED_OUT) `touch PWNED_OUT2`")
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PATH=${WORK}/bin
          ${XVAL} validate ${WORK}/scene/${_scene_name} -o ${_out} --jobs 3 --timeout 20 --batch 1
          --tolerances ${CMAKE_CURRENT_LIST_DIR}/../../reference/tolerances.json
  WORKING_DIRECTORY ${WORK}/cwd
  RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_VARIABLE out)
message("exit ${rc}\n${err}")
if(NOT rc EQUAL 2)
  message(FATAL_ERROR "exit status ${rc}, expected 2 (both stand-ins fail)")
endif()

# 1. Nothing ran.
file(GLOB_RECURSE _pwned LIST_DIRECTORIES true ${WORK}/*PWNED_* /tmp/PWNED_*)
foreach(_p ${_pwned})
  get_filename_component(_n ${_p} NAME)
  if(_n MATCHES "^PWNED_")
    message(FATAL_ERROR "a scene string was executed: ${_p} exists")
  endif()
endforeach()

# 2. Fixed command lines.
# Arguments may hold ';' too: each goes into its own variable, PREFIX_<i>.
function(read_args tool prefix)
  if(NOT EXISTS ${WORK}/${tool}.args/argc)
    message(FATAL_ERROR "${tool} was not started")
  endif()
  file(READ ${WORK}/${tool}.args/argc _argc)
  string(STRIP "${_argc}" _argc)
  foreach(_i RANGE 1 ${_argc})
    file(READ ${WORK}/${tool}.args/${_i} _a)
    set(${prefix}_${_i} "${_a}" PARENT_SCOPE)
  endforeach()
  set(${prefix}_N ${_argc} PARENT_SCOPE)
endfunction()
read_args(povray _pov)
# scene.ini, then the attempt's output name (+O, xval's own: no scene string).
if(NOT _pov_N EQUAL 2 OR NOT _pov_1 STREQUAL "scene.ini" OR NOT _pov_2 MATCHES "^\\+Opovray-[0-9a-f]+\\.png$")
  message(FATAL_ERROR "povray was started with ${_pov_N} arguments, the first ${_pov_1}, the second ${_pov_2}")
endif()
read_args(blender _bl)
# Blender runs twice (Cycles and EEVEE, in either order: validate's jobs
# run in parallel); the stand-in keeps the last start's arguments, which
# end in "--engine cycles" or "--engine eevee".
if(NOT _bl_N EQUAL 14)
  message(FATAL_ERROR "blender was started with ${_bl_N} arguments")
endif()
if(NOT _bl_14 STREQUAL "cycles" AND NOT _bl_14 STREQUAL "eevee")
  message(FATAL_ERROR "blender's engine argument is \"${_bl_14}\"")
endif()
set(_expected_bl 1 "-b" 2 "--factory-startup" 3 "-noaudio" 4 "-P" 6 "--" 7 "--gltf" 9 "--out"
                 11 "--mode" 12 "model" 13 "--engine")
while(_expected_bl)
  list(POP_FRONT _expected_bl _i _v)
  if(NOT "${_bl_${_i}}" STREQUAL "${_v}")
    message(FATAL_ERROR "blender argument ${_i} is \"${_bl_${_i}}\", expected \"${_v}\"")
  endif()
endwhile()
if(NOT _bl_5 MATCHES "/render_gltf\\.py$")
  message(FATAL_ERROR "blender's script is ${_bl_5}")
endif()
string(FIND "${_bl_8}" "${_out}/" _at_gltf)
string(FIND "${_bl_10}" "${_out}/" _at_exr)
if(NOT _at_gltf EQUAL 0 OR NOT _at_exr EQUAL 0 OR NOT EXISTS "${_bl_8}")
  message(FATAL_ERROR "blender's paths are not files in the output folder: ${_bl_8} ${_bl_10}")
endif()

# 3. No scene string in the generated files. (Paths hold ';', so no
# CMake lists of them: the case folder is found from blender's argument.)
get_filename_component(_blender_work "${_bl_8}" DIRECTORY)
get_filename_component(_case "${_blender_work}" DIRECTORY)
# The glTF carries the scene description once, as data: a JSON string in
# scenes[0].extras.xval that the Blender script reads with json.loads. It
# must hold the name exactly; the rest of the glTF holds no scene string.
file(READ "${_bl_8}" _gltf)
string(JSON _desc GET "${_gltf}" scenes 0 extras xval)
string(JSON _desc_name GET "${_desc}" name)
string(JSON _desc_tex GET "${_desc}" material texture path)
file(READ ${SCENE} _scene_text)
string(JSON _scene_name_value GET "${_scene_text}" name)
if(NOT _desc_name STREQUAL _scene_name_value OR NOT _desc_tex STREQUAL "texture.png")
  message(FATAL_ERROR "the glTF's scene description changed the strings: ${_desc_name} / ${_desc_tex}")
endif()
string(JSON _gltf_rest REMOVE "${_gltf}" scenes 0 extras xval)
file(WRITE ${WORK}/gltf_without_description.json "${_gltf_rest}")
foreach(_f "${_case}/povray.work/scene.pov" "${_case}/povray.work/scene.ini"
           "${WORK}/gltf_without_description.json")
  if(NOT EXISTS "${_f}")
    message(FATAL_ERROR "${_f} was not written")
  endif()
  file(STRINGS "${_f}" _lines)
  set(_i 0)
  foreach(_line IN LISTS _lines)
    math(EXPR _i "${_i} + 1")
    if(_f MATCHES "\\.pov$" AND _i EQUAL 1)
      if(NOT _line MATCHES "^// Generated by xval" OR _line MATCHES "[\"#{}`$]")
        message(FATAL_ERROR "${_f}: first line not a safe comment: ${_line}")
      endif()
      continue()
    endif()
    if(_line MATCHES "PWNED|#declare [EX] |import os")
      message(FATAL_ERROR "${_f}:${_i} carries a scene string: ${_line}")
    endif()
  endforeach()
endforeach()

# 4. The case folder is directly in the output folder, named as the scene.
get_filename_component(_parent "${_case}" DIRECTORY)
get_filename_component(_case_name "${_case}" NAME)
if(NOT _parent STREQUAL _out OR NOT _case_name MATCHES "^n [$][(]touch PWNED_NAME[)]")
  message(FATAL_ERROR "case folder ${_case} is not ${_out}/<scene name>")
endif()
if(NOT EXISTS "${_out}/results.json")
  message(FATAL_ERROR "no results.json")
endif()
