// Flat shading's normal of each triangle: the unit winding normal
//   g = (P1 - P0) x (P2 - P0) / |(P1 - P0) x (P2 - P0)|
// turned around where it disagrees with the vertex normals,
//   g . (n0 + n1 + n2) < 0  ->  -g,
// and 0 for a degenerate triangle (|g| = 0). Formed in double from the
// mesh's attributes (the float32-rounded values every renderer traces).
// The reference renderer shades with it, and the glTF export carries it
// to the Blender harness, so both use the very same normals.
#pragma once

#include <glm/glm.hpp>

#include <vector>

#include "geometry/mesh.h"

namespace xval {

inline std::vector<glm::dvec3> flatNormals(const TriangleMesh& m) {
  std::vector<glm::dvec3> out;
  out.reserve(m.triangles.size());
  for (const auto& t : m.triangles) {
    glm::dvec3 g = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                              m.positions[t[2]] - m.positions[t[0]]);
    const double len = glm::length(g);
    g = len > 0.0 ? g / len : glm::dvec3(0.0);
    if (glm::dot(g, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]) < 0.0) g = -g;
    out.push_back(g);
  }
  return out;
}

}  // namespace xval
