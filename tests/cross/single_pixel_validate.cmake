# xval validate on one scene, then one pixel of POV-Ray's render painted
# magenta (oiiotool) and the compare step run again: the case must fail
# (exit 1) on that pixel, as the worst unexplained one of the pair, though
# it is one pixel in 65,536. The report of that run is what
# report_pixels_in_chromium.cmake looks at.
# -DXVAL=... -DSCENE=... -DTOLERANCES=... -DOUT=... -DX=... -DY=...
find_program(OIIOTOOL oiiotool REQUIRED)
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${XVAL} validate ${SCENE} --tolerances ${TOLERANCES} -o ${OUT}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the scene does not pass before the change (exit ${rc}):\n${out}${err}")
endif()
get_filename_component(name ${SCENE} NAME_WE)
set(exr ${OUT}/${name}/povray.exr)
execute_process(COMMAND ${OIIOTOOL} ${exr} --ch R,G,B,A --fill:color=1,0,1,1 1x1+${X}+${Y} -o ${exr}.new.exr
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "oiiotool failed (${rc}): ${err}")
endif()
file(RENAME ${exr}.new.exr ${exr})
execute_process(COMMAND ${XVAL} validate --plan ${OUT}/jobs.json --compare-only
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
file(READ ${OUT}/results.json results)
string(JSON pair0 GET "${results}" cases 0 pairs 0 pair)
string(JSON pass0 GET "${results}" cases 0 pairs 0 pass)
string(JSON wx GET "${results}" cases 0 pairs 0 metrics worst_unexplained_pixel 0)
string(JSON wy GET "${results}" cases 0 pairs 0 metrics worst_unexplained_pixel 1)
string(JSON within GET "${results}" cases 0 pairs 0 metrics fraction_within)
if(NOT rc EQUAL 1 OR NOT pair0 STREQUAL "reference-povray" OR pass0 OR NOT wx EQUAL X OR NOT wy EQUAL Y
   OR within LESS 0.999)
  message(FATAL_ERROR "one wrong pixel: expected exit 1 and ${pair0} failing at (${X}, ${Y}) with more than 99.9% "
                      "within; got exit ${rc}, pass ${pass0}, worst unexplained (${wx}, ${wy}), within ${within}\n${err}")
endif()
