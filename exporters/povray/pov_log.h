// The timings POV-Ray 3.7 writes to its log (its statistics blocks):
//   Parser Time
//     Parse Time:       0 hours  0 minutes  0 seconds (0.186 seconds)
//     Bounding Time:    0 hours  0 minutes  0 seconds (0.043 seconds)
//   Render Time:
//     Photon Time:      No photons
//     Trace Time:       0 hours  0 minutes  0 seconds (0.002 seconds)
// Each figure is the wall time in brackets. A block that is missing, cut
// off or unreadable ("No photons", garbage, a negative or non-finite
// number) gives -1 (absent), never 0. The last occurrence of a label wins.
#pragma once

#include <filesystem>
#include <string_view>

namespace xval {

struct PovLogTimes {
  double parse_seconds = -1.0;     // reading the SDL
  double bounding_seconds = -1.0;  // building the bounding hierarchy (after parsing)
  double photon_seconds = -1.0;    // photon shooting (-1 also for "No photons")
  double trace_seconds = -1.0;     // the render itself
};

PovLogTimes povLogTimes(std::string_view log_text);
// The log file's timings; an unreadable file gives all absent.
PovLogTimes povLogTimesOfFile(const std::filesystem::path& log);

}  // namespace xval
