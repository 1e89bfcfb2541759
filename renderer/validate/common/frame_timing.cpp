// The frame timing loop (validate/common/frame_timing.h).
#include "validate/common/frame_timing.h"

#include <algorithm>
#include <chrono>

#include <time.h>

namespace xval {

Spread spread(std::vector<double> v) {
  Spread s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.n = v.size();
  s.min = v.front(), s.max = v.back();
  s.median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  return s;
}

double processCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

FrameTimes timeFrames(const std::function<void()>& frame, const FrameBudget& budget, WarmUp warm_up) {
  using Clock = std::chrono::steady_clock;
  FrameTimes out;
  double sum = 0.0;
  auto timed = [&]() {
    const auto t0 = Clock::now();
    const double c0 = processCpuSeconds();
    frame();
    out.cpu_s.push_back(processCpuSeconds() - c0);
    out.wall_s.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  };
  if (warm_up == WarmUp::Render) {
    timed();
    if (out.wall_s.back() >= budget.max_seconds) {
      out.warmup_frame_timed = true;
      sum = out.wall_s.back();
    } else {
      out.wall_s.clear(), out.cpu_s.clear();
    }
  }
  while (int(out.wall_s.size()) < budget.frames && (out.wall_s.empty() || sum < budget.max_seconds)) {
    timed();
    sum += out.wall_s.back();
  }
  return out;
}

}  // namespace xval
