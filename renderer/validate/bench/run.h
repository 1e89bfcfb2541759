// `xval bench`: whole-frame timings of one scene, in one run, side by side,
// for the renderers asked for, in registry order (renderers/registry.h):
//   reference float:  the fast path (Embree 16-ray packets or the raster,
//                     float shading);
//   reference double: the exact reference path;
//   a real-time one:  (a renderer with prepare_frames, e.g. gl) the scene
//                     prepared once, then `frames` frames after one warm-up
//                     frame, each drawn and waited for, nothing read back;
//                     printed also as frames per second (1 / median frame);
//   the others:       the external renderer's own render time as it reports
//                     it, and its whole process (export, start-up, parse,
//                     render, read back).
// For the reference renderer the scene is prepared once (tessellation,
// texture, BVH: "setup", reported apart) and then `frames` frames are
// rendered into one image after one warm-up frame (validate/common/
// frame_timing.h): a frame is rays + shading + writing the pixels, without
// diagnostics (what an interactive renderer redoes every frame; the paper's
// Table 2 counts the same). Frame figures are wall-clock and the process's
// CPU time (all threads); on a busy machine only the CPU time means much.
// With the reference double path also the frame at 16 spp (the target's
// spp), when the frames above were at another: at most 3 frames after a
// warm-up ("reference_double_16spp"; a scene over the budget at 16 spp is
// not timed and its target line says so).
// With the reference renderer also, per precision, the validate-style
// frame (diagnostics on: every channel a validate run's render has) with
// the precision probes and without them (RenderOptions::precision_probes:
// what they cost); then the whole process of `xval render SCENE -o X.exr`
// (the scene's precision, default outputs), the same with
// --no-diagnostics, and `xval --version` (start-up and exit), each `runs`
// times, run as child processes of this xval (/proc/self/exe); and that
// render's stages timed once in this process (scene load, set-up, frame,
// EXR write with its read-back); and validate's reference job of the
// scene (validate/common/reference_job.h: double, one thread, every
// diagnostic channel, its EXR with the read-back and its preview PNG) with
// the precision probes and without them, alternating, `runs` times each,
// wall and CPU, and the probes' share of it. Last, one line per target of
// docs/performance.md ("Targets"): the target, the measured figure, met or
// not, or why it was not measured.
// Every figure is the median over the repetitions with its spread
// (min..max); ratios are of medians, against the reference float frame.
//
// Parameters (BenchRequest) and their defaults:
//   renderers  ids, any of the registry's (default: its every-scene ones)
//   frames     20   reference frames per precision (and real-time frames)
//                   after the warm-up
//   runs       3    runs of each external renderer
//   spp        0    the scene's render.spp (else a perfect square, checked
//                   by the caller, and against the budget here)
//   threads    0    all hardware threads
//   precision  "both" | "float" | "double": the reference paths timed
//   timeout_s  600  per external render
//   json       ""   also write the figures to this file (atomically)
#pragma once

#include <string>
#include <vector>

#include "scene_file/scene_budget.h"

namespace xval::bench {

struct BenchRequest {
  std::string scene_file;
  std::vector<std::string> renderers;
  int frames = 20, runs = 3, spp = 0, threads = 0;
  std::string precision = "both";
  double timeout_seconds = 600.0;
  std::string json;
  Budget budget;
};

// Prints the figures on stdout; returns 0. Throws std::runtime_error naming
// an unknown renderer, SceneError for a bad scene, and the renderers' errors.
int runBench(const BenchRequest& request);

}  // namespace xval::bench
