# `xval validate` on a folder holding four invalid scenes and a valid one:
# one run names every invalid scene with its field and value (not only the
# first), exits 2 and renders nothing (no plan, no case folder).
# Arguments: XVAL, BAD (tests/cli/bad_scenes), SCENE (a valid scene), WORK.
foreach(_v XVAL BAD SCENE WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "every_invalid_scene.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/scenes)
foreach(_f unknown_field wrong_type out_of_range negative_number)
  file(COPY_FILE ${BAD}/${_f}.json ${WORK}/scenes/${_f}.json)
endforeach()
file(COPY_FILE ${SCENE} ${WORK}/scenes/valid.json)
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)

run_xval(2 _o validate ${WORK}/scenes --renderers reference,golden -o ${WORK}/out)
expect("${_o}" "4 of 5 scenes are invalid \\(nothing rendered\\)" "the count")
foreach(_expected
    "negative_number.json: objects\\[0\\].radius: expected a number > 0, got -1"
    "out_of_range.json: camera.fov_y_deg: expected a number in \\[1e-06, 180\\), got 180"
    "unknown_field.json: camera.fov: unknown field \\(value 45\\)"
    "wrong_type.json: camera.width: expected an integer in \\[1, 16384\\], got \"16\"")
  expect("${_o}" "${_expected}" "every invalid scene named with its field and value")
endforeach()
if(EXISTS ${WORK}/out/jobs.json OR EXISTS ${WORK}/out/tiny)
  message(FATAL_ERROR "validate planned or rendered although scenes are invalid")
endif()
