// Dropping the triangles every renderer must not be given
// (degenerate_triangles.h states the rule and why).
#include "geometry/degenerate_triangles.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace xval {

DroppedTriangles dropDegenerateTriangles(const std::vector<glm::u32vec3>& triangles) {
  DroppedTriangles out;
  // Each triangle's indices sorted, with its position: sorted, twins are
  // adjacent and the first of each run is the earliest.
  std::vector<std::array<std::uint32_t, 4>> keys;
  keys.reserve(triangles.size());
  std::vector<char> keep(triangles.size(), 1);
  for (size_t i = 0; i < triangles.size(); ++i) {
    std::array<std::uint32_t, 3> s{triangles[i][0], triangles[i][1], triangles[i][2]};
    std::sort(s.begin(), s.end());
    if (s[0] == s[1] || s[1] == s[2]) {
      keep[i] = 0, ++out.repeated_index;
      continue;
    }
    keys.push_back({s[0], s[1], s[2], std::uint32_t(i)});
  }
  std::sort(keys.begin(), keys.end());
  for (size_t k = 1; k < keys.size(); ++k)
    if (keys[k][0] == keys[k - 1][0] && keys[k][1] == keys[k - 1][1] && keys[k][2] == keys[k - 1][2])
      keep[keys[k][3]] = 0, ++out.duplicates;
  out.kept.reserve(triangles.size() - out.dropped());
  for (size_t i = 0; i < triangles.size(); ++i)
    if (keep[i]) out.kept.push_back(triangles[i]);
  return out;
}

}  // namespace xval
