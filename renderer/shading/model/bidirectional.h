// Lighting model `bidirectional`: Forsyth's family (seed 002), a second
// light colour from behind (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name | type      | default   | range | meaning                           |
//   | c0   | [r, g, b] | [1, 1, 1] | >= 0  | the colour facing the light       |
//   | c2   | [r, g, b] | [0, 0, 0] | >= 0  | the colour facing away from it    |
//
//   per light: c0 clamp(x) + c2 clamp(-x), x = N.L;
//   F = C (x) (A + sum att Lc (x) that)
//   Math: models::biDirectional (shading/models.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct BiDirectional {
  static constexpr const char* kName = "bidirectional";
  glm::dvec3 c0{1.0};
  glm::dvec3 c2{0.0};

  static auto params() {
    using namespace model;
    using M = BiDirectional;
    return std::tuple{ColourParam<M>{"c0", &M::c0, kNonNegative}, ColourParam<M>{"c2", &M::c2, kNonNegative}};
  }
};

}  // namespace xval
