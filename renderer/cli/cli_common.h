// Small pieces several subcommands share: checking a samples-per-pixel
// option, time limits, budget options, and writing a JSON file of figures
// (the median/min/max of timings: validate/common/frame_timing.h).
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "files/atomic_write.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene_file/scene_budget.h"
#include "validate/common/frame_timing.h"  // Spread, spread()

namespace xval::cli {

// Throws unless spp is a perfect square in [1, 256] (an n x n stratified
// grid); `option` names the option in the message, e.g. "--spp".
inline void requirePerfectSquareSpp(int spp, const std::string& option) {
  int n = 1;
  while (n * n < spp) ++n;
  if (spp < 1 || spp > 256 || n * n != spp)
    throw std::runtime_error(option + " " + std::to_string(spp) +
                             ": expected a perfect square (1, 4, 9, ..., 256)");
}

// A time limit in seconds: a finite number in (0, kMaxSeconds]. NaN, inf,
// 0 and negatives are refused (a NaN or infinite time-out would never
// expire; CLI::PositiveNumber lets NaN through).
inline constexpr double kMaxSeconds = 7 * 24 * 3600.0;  // a week
inline const CLI::Validator Seconds(
    [](std::string& text) -> std::string {
      double v = 0;
      if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v <= 0 || v > kMaxSeconds)
        return "expected seconds, a number greater than 0 and at most " + std::to_string(int(kMaxSeconds)) +
               " (a week), got " + text;
      return "";
    },
    "SECONDS", "Seconds");
// A positive finite factor (NaN and inf refused).
inline const CLI::Validator FinitePositive(
    [](std::string& text) -> std::string {
      double v = 0;
      if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v <= 0)
        return "expected a finite number greater than 0, got " + text;
      return "";
    },
    "POSITIVE", "FinitePositive");
// --max-triangles, --max-samples, --max-memory-mb and --allow-large: the
// total budget of a render (scene_file/scene_budget.h), checked when the scene
// is loaded and whenever a command changes its size, spp or tessellation.
struct BudgetOptions {
  Budget budget;
  bool allow_large = false;
  Budget get() const { return allow_large ? unlimitedBudget() : budget; }
};
inline void addBudgetOptions(CLI::App* cmd, BudgetOptions& o) {
  const Budget d;
  cmd->add_option("--max-triangles", o.budget.max_triangles,
                  "Most triangles over all objects (default " + std::to_string(d.max_triangles) + ")")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-samples", o.budget.max_samples,
                  "Most samples, width x height x spp (default " + std::to_string(d.max_samples) + ")")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-memory-mb", o.budget.max_memory_mb,
                  "Most estimated memory of a render, MiB (default " + std::to_string(d.max_memory_mb) + ")")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--allow-large", o.allow_large,
                "Lift the three limits above (the per-field limits of the scene format remain)");
}

// Writes j (indented) to `file`; throws naming the file when it cannot.
inline void writeJsonFile(const std::string& file, const nlohmann::json& j) {
  writeFileAtomically(file, j.dump(2) + "\n");
}

}  // namespace xval::cli
