# A run of `xval validate` into a folder an earlier run wrote removes, per
# case it compares, the comparison outputs (validate/compare_outputs.h:
# diff_*.exr, heat_*.png, heat_bound_*.png, crop_*.png) its results do not
# name, and nothing else, with a stand-in POV-Ray that copies a prepared
# image:
#   1. a, b, c validated; a's POV-Ray image is lit from elsewhere, so its
#      pair fails and the compare writes crops of its worst pixels;
#   2. an earlier run's outputs planted in a (a pair that no longer exists,
#      of each kind) and in b, with a user's files: notes, a file of another
#      extension, symbolic links named like the outputs, one to a file
#      outside the folder; c's scene file removed;
#   3. a validated alone, its POV-Ray image now right: a's crops and the
#      planted outputs are gone from a and b (b is kept, compared again),
#      the count said on stderr; the user's files, the links and what they
#      point to stay; a and b keep what their results name; c, dropped,
#      belongs to no case and keeps its folder as it was.
# Arguments: XVAL, SCENE (a small scene named "tiny", lit by a directional
# light along -0.3, -0.4, -1), WORK.
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)
require_defined(stale_outputs.cmake XVAL SCENE WORK)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/bin ${WORK}/scenes ${WORK}/wrong ${WORK}/outside)
write_renamed_scenes(a b c)
# a lit from the other side, for the wrong POV-Ray image.
file(READ ${WORK}/scenes/a.json _text)
string(REGEX REPLACE "-0\\.3,[ \n]*-0\\.4" "0.3, 0.4" _wrong "${_text}")
if(_wrong STREQUAL _text)
  message(FATAL_ERROR "stale_outputs.cmake: could not turn ${SCENE}'s light")
endif()
file(WRITE ${WORK}/wrong/a.json "${_wrong}")
run(0 ${XVAL} render ${WORK}/wrong/a.json -o ${WORK}/wrong_a.exr --precision double -q)
# The stand-in finds its case by the component after out/ in its work
# folder and copies ${WORK}/povray_<case>.exr.
write_povray_stand_in(${WORK}/bin
  "s=$(/bin/echo \"$PWD\" | /bin/sed -n 's|.*/out/\\([^/]*\\)/.*|\\1|p')\n/bin/cp \"${WORK}/povray_$s.exr\" \"$out\"")

function(validate expect_rc)
  validate_with_stand_ins(${expect_rc} ${WORK}/bin ${ARGN} -o ${WORK}/out --renderers reference,povray --jobs 2
                          --timeout 60)
  set(err "${err}" PARENT_SCOPE)
endfunction()
# The names of a folder's entries, sorted.
function(names var dir)
  file(GLOB _all LIST_DIRECTORIES true RELATIVE ${dir} ${dir}/*)
  list(SORT _all)
  set(${var} "${_all}" PARENT_SCOPE)
endfunction()

# 1. a fails (crops written), b and c pass.
file(COPY_FILE ${WORK}/wrong_a.exr ${WORK}/povray_a.exr)
file(COPY_FILE ${WORK}/ref_b.exr ${WORK}/povray_b.exr)
file(COPY_FILE ${WORK}/ref_c.exr ${WORK}/povray_c.exr)
validate(1 ${WORK}/scenes)
file(GLOB _crops RELATIVE ${WORK}/out/a ${WORK}/out/a/crop_reference-povray_*.png)
list(LENGTH _crops _n_crops)
if(_n_crops EQUAL 0)
  message(FATAL_ERROR "a's failing pair wrote no crops: the test cannot see them go")
endif()
names(_c_before ${WORK}/out/c)
names(_b_before ${WORK}/out/b)

# 2. An earlier run's outputs of a pair that no longer exists, one of each
#    kind, in a (beside the real crops) and in b; the user's files.
foreach(_s a b)
  foreach(_f diff_reference-gone.exr heat_reference-gone.png heat_bound_reference-gone.png
             crop_reference-gone_worst_unexplained_reference.png)
    file(WRITE ${WORK}/out/${_s}/${_f} "an earlier run's\n")
  endforeach()
endforeach()
file(WRITE ${WORK}/out/a/notes.txt "the user's\n")
file(WRITE ${WORK}/out/a/heat_reference-gone.txt "the user's, another extension\n")
file(WRITE ${WORK}/outside/crop_theirs.png "outside the folder\n")
file(CREATE_LINK ${WORK}/outside/crop_theirs.png ${WORK}/out/a/crop_link_worst_unexplained_heat.png SYMBOLIC)
file(CREATE_LINK ${WORK}/outside ${WORK}/out/a/heat_folder.png SYMBOLIC)
file(REMOVE ${WORK}/scenes/c.json)

# 3. a alone, right this time: b kept, c dropped.
file(COPY_FILE ${WORK}/ref_a.exr ${WORK}/povray_a.exr)
validate(0 ${WORK}/scenes/a.json)
expect_in("${err}" "keeping 1 earlier cases")
expect_in("${err}" "c.json: dropped: the scene file no longer exists")
file(GLOB _left ${WORK}/out/a/crop_reference-* ${WORK}/out/*/crop_reference-gone_* ${WORK}/out/*/*reference-gone.exr ${WORK}/out/*/*reference-gone.png)
if(_left)
  message(FATAL_ERROR "stale comparison outputs left: ${_left}")
endif()
# The user's files, the links and what they point to stay.
foreach(_f notes.txt heat_reference-gone.txt)
  if(NOT EXISTS ${WORK}/out/a/${_f})
    message(FATAL_ERROR "the user's file ${WORK}/out/a/${_f} was removed")
  endif()
endforeach()
foreach(_f crop_link_worst_unexplained_heat.png heat_folder.png)
  if(NOT IS_SYMLINK ${WORK}/out/a/${_f})
    message(FATAL_ERROR "the user's symbolic link ${WORK}/out/a/${_f} was removed")
  endif()
endforeach()
file(READ ${WORK}/outside/crop_theirs.png _theirs)
expect_eq("the file a link points to" "${_theirs}" "outside the folder\n")
# What the results name is there: each case's heat map and bound map, and
# the difference EXR beside them.
file(READ ${WORK}/out/results.json _r)
foreach(_i 0 1)
  get_json(_case "${_r}" cases ${_i} scene)
  get_json(_heat "${_r}" cases ${_i} pairs 0 heat_map)
  expect_eq("${_case}'s heat map" "${_heat}" "${_case}/heat_reference-povray.png")
  get_json(_bound "${_r}" cases ${_i} pairs 0 bound_map)
  foreach(_f ${_heat} ${_bound} ${_case}/diff_reference-povray.exr)
    if(NOT EXISTS ${WORK}/out/${_f})
      message(FATAL_ERROR "${WORK}/out/${_f}, of this run, is missing")
    endif()
  endforeach()
endforeach()
# b, kept, has what it had; c, dropped, is as it was.
names(_b_after ${WORK}/out/b)
expect_eq("b's files" "${_b_after}" "${_b_before}")
names(_c_after ${WORK}/out/c)
expect_eq("c's files" "${_c_after}" "${_c_before}")
# The count said, per case that lost files.
math(EXPR _n_a "${_n_crops} + 4")
expect_in("${err}" "xval validate: ${WORK}/out/a: removed ${_n_a} stale comparison outputs (diff_*.exr, heat_*.png, crop_*.png) of an earlier run that this run's results do not name")
expect_in("${err}" "xval validate: ${WORK}/out/b: removed 4 stale comparison outputs")
if(err MATCHES "out/c: removed")
  message(FATAL_ERROR "c, no case of this run, had files removed:\n${err}")
endif()
