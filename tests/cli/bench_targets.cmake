# xval bench prints, beside the frames, the validate-style frames (with and
# without the precision probes), the whole process of `xval render` with
# its stages, validate's reference job of the scene with and without the
# probes and their share of it, and one line per performance target (docs/performance.md,
# "Targets") with the measured figure; --json holds the same. With gl in
# --renderers, the gl frame's target has its figure; without, it says why not.
# Arguments: XVAL, SCENE (a small scene file), WORK.
foreach(_v XVAL SCENE WORK)
  if(NOT DEFINED ${_v})
    message(FATAL_ERROR "bench_targets.cmake: -D${_v}=... is required")
  endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
include(${CMAKE_CURRENT_LIST_DIR}/xval_run.cmake)
run_xval(0 _o bench ${SCENE} --renderers reference --frames 1 --runs 1 --json ${WORK}/bench.json)
foreach(_p float double)
  expect("${_o}" "reference_${_p}_diagnostics +frame +[0-9.]+ ms" "the ${_p} validate-style frame")
  expect("${_o}" "reference_${_p}_diagnostics_no_probes +frame +[0-9.]+ ms" "the ${_p} frame without probes")
  expect("${_o}" "precision probes <= 10% of the validate-style ${_p} frame +[0-9]+% of its CPU time +(met|not met)"
         "the ${_p} probes target")
endforeach()
expect("${_o}" "xval_render +whole process +[0-9.]+ ms" "the whole process of xval render")
expect("${_o}" "stages: scene load [0-9.]+ ms, set-up [0-9.]+ ms, frame with diagnostics [0-9.]+ ms, EXR write"
       "the render's stages")
expect("${_o}" "reference float frame <= 3 ms \\(wall median, 1 spp as asked\\) +[0-9.]+ ms +(met|not met)"
       "the float frame target")
# The double frame at 16 spp: timed apart (the scene's spp is 1), its target
# line with the CPU and the wall median.
expect("${_o}" "reference_double_16spp +frame +[0-9.]+ ms .*CPU time +[0-9.]+ ms" "the double frame at 16 spp")
expect("${_o}" "reference double frame at 16 spp <= 0.25 s \\(CPU median\\) +[0-9.]+ ms \\(wall median [0-9.]+ ms\\) +(met|not met)"
       "the 16-spp double frame target")
expect("${_o}" "validate ref. job +with probes +[0-9.]+ ms .*CPU time +[0-9.]+ ms" "validate's reference job")
expect("${_o}" "without probes +[0-9.]+ ms .*CPU time +[0-9.]+ ms" "validate's reference job without probes")
expect("${_o}" "the probes' share of the job: -?[0-9]+% of its CPU time, -?[0-9]+% of its wall time" "the probes' share")
expect("${_o}" "precision probes <= 10% of validate's reference job \\(CPU\\) +-?[0-9]+% of its CPU time +(met|not met)"
       "the reference job's probes target")
# POV-Ray was not asked for: the process target says why it has no figure.
expect("${_o}" "5x faster than POV-Ray's +not measured: needs reference and povray" "the process target")
expect("${_o}" "gl frame <= 20 ms \\(wall median\\) +not measured: needs gl in --renderers" "the gl frame target")
file(READ ${WORK}/bench.json _j)
string(JSON _n LENGTH "${_j}" targets)
if(NOT _n EQUAL 7)
  message(FATAL_ERROR "bench.json: ${_n} targets, expected 7:\n${_j}")
endif()
string(JSON _s GET "${_j}" xval_render process_median_s)
if(NOT _s GREATER 0)
  message(FATAL_ERROR "bench.json: xval_render.process_median_s is ${_s}, expected > 0")
endif()
string(JSON _s GET "${_j}" reference_double_16spp spp)
if(NOT _s EQUAL 16)
  message(FATAL_ERROR "bench.json: reference_double_16spp.spp is ${_s}, expected 16")
endif()
string(JSON _s GET "${_j}" validate_reference_job_no_probes cpu_median_s)
if(NOT _s GREATER 0)
  message(FATAL_ERROR "bench.json: validate_reference_job_no_probes.cpu_median_s is ${_s}, expected > 0")
endif()

# gl's frames: the gl target with its figure, met or not, in the JSON too.
run_xval(0 _o bench ${SCENE} --renderers gl --frames 2 --runs 1 --json ${WORK}/bench_gl.json)
expect("${_o}" "gl frame <= 20 ms \\(wall median\\) +[0-9.]+ ms \\([0-9.]+ frames per second\\) +(met|not met)"
       "the gl frame target")
file(READ ${WORK}/bench_gl.json _j)
string(JSON _n LENGTH "${_j}" targets)
math(EXPR _last "${_n} - 1")
string(JSON _what GET "${_j}" targets ${_last} target)
string(JSON _at_all GET "${_j}" targets ${_last} measured_at_all)
if(NOT _what STREQUAL "gl frame <= 20 ms (wall median)" OR NOT _at_all)
  message(FATAL_ERROR "bench_gl.json: the last target is \"${_what}\", measured_at_all ${_at_all}; "
                      "expected the gl frame's, measured:\n${_j}")
endif()
