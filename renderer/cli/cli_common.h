// Small pieces several subcommands share: checking a samples-per-pixel
// option, and the median/min/max summary of repeated timings.
#pragma once

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

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

// Median, min and max of repeated measurements (n = 0: all zero).
struct Spread {
  double median = 0, min = 0, max = 0;
  size_t n = 0;
};

inline Spread spread(std::vector<double> v) {
  Spread s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  s.n = v.size();
  s.min = v.front(), s.max = v.back();
  s.median = v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  return s;
}

}  // namespace xval::cli
