// Timing repeated frames of one prepared render: the one timing loop of
// `xval tradeoff` and `xval bench`.
//
// timeFrames(frame, budget, warm_up) renders frames with `frame()` and
// times each, wall clock (steady_clock) and this process's CPU time over
// all its threads (CLOCK_PROCESS_CPUTIME_ID):
//   - WarmUp::Render: one warm-up frame first. When it alone takes
//     budget.max_seconds or more it is not rendered again: it is the one
//     timed frame (warmup_frame_timed). Otherwise it is not counted.
//   - WarmUp::AlreadyDone: the caller has warmed up (e.g. with diagnostics
//     on); nothing is rendered before the timed frames.
//   Then frames are timed while fewer than budget.frames are timed and
//   (none is timed yet or their wall times add up to less than
//   budget.max_seconds): at least one and at most budget.frames timed
//   frames. Defaults: 5 frames, no time limit (infinity).
//
// spread(v): the median (the mean of the middle two for an even count),
// min and max of v; all zero for an empty v.
#pragma once

#include <functional>
#include <limits>
#include <vector>

namespace xval {

struct Spread {
  double median = 0, min = 0, max = 0;
  size_t n = 0;
};
Spread spread(std::vector<double> v);

struct FrameBudget {
  int frames = 5;
  double max_seconds = std::numeric_limits<double>::infinity();
};

enum class WarmUp { Render, AlreadyDone };

struct FrameTimes {
  std::vector<double> wall_s, cpu_s;  // per timed frame
  bool warmup_frame_timed = false;
};

FrameTimes timeFrames(const std::function<void()>& frame, const FrameBudget& budget, WarmUp warm_up);

// CPU seconds used by this process so far, over all its threads.
double processCpuSeconds();

}  // namespace xval
