// `xval tradeoff`: speed against accuracy of the reference renderer's
// knobs, on one scene, in one process, side by side. sweep.h defines the
// sweep, the converged reference and the error; this runs it.
//
// TradeoffRun (defaults):
//   scene_file                  the scene (loaded with `budget`)
//   out                         the output folder (created; locked)
//   frames = 5                  timed frames per configuration after one
//                               warm-up frame; the figure is their median
//                               wall time, with min..max
//   max_seconds = 3             stop timing a configuration once its timed
//                               frames add up to this (frame_timing.h)
//   threads = 0                 render threads (0 = every hardware thread)
//   quick = false               sweep.h's quick sweep; the reference
//                               defaults to 16 spp and tessellation x2
//   reference_spp = 0           converged reference's samples (0: 64, or
//                               16 with quick; a perfect square)
//   reference_tessellation = 0  its segments factor (0: 4, or 2 with quick)
//   width, height = 0           override the camera's resolution (0: the
//                               scene's; the field of view is kept)
//   metric = "rmse"             the error on the Pareto plot and front: an
//                               error of the metric table (sweep.h:
//                               tradeoffAxis; e.g. rmse, ciede2000, flip)
//   images = false              also write DIR/images/<id>.exr
//
// Each configuration is prepared once (PreparedScene: tessellation,
// texture, BVH; "setup", reported apart), rendered once to warm up, then
// timed frame by frame without diagnostics (frame_timing.h); its error is
// that of its last frame against the converged reference. The converged
// configuration is itself a row: the reference frame is its warm-up, and
// it is always rendered at least once more; its error, that of the later
// frame, is 0 when rendering is deterministic (a check). The Pareto front
// (sweep.h: paretoFront) leaves the converged row out and takes the
// reference's largest convergence residual as the error tolerance.
//
// Writes DIR/tradeoff.json (format xval-tradeoff/1, with provenance.h's
// record), tradeoff.tsv and tradeoff.md (tables.h) and the Pareto plot
// (pareto_plot.h). Progress on stderr. Throws on an error (bad scene,
// gnuplot missing, ...).
#pragma once

#include <string>

#include "scene_file/scene_budget.h"

namespace xval {

struct TradeoffRun {
  std::string scene_file, out, metric = "rmse";
  int frames = 5, threads = 0, reference_spp = 0, width = 0, height = 0;
  double max_seconds = 3.0, reference_tessellation = 0.0;
  bool quick = false, images = false;
  Budget budget;
};

void runTradeoff(const TradeoffRun& run);

}  // namespace xval
