// Lighting model `trilight`: Forsyth's trilight (seed 002), three colours
// by N.L; lambert, bidirectional and hemispherical are special cases
// (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name | type      | default   | range | meaning                           |
//   | c0   | [r, g, b] | [1, 1, 1] | >= 0  | the colour facing the light       |
//   | c1   | [r, g, b] | [0, 0, 0] | >= 0  | the colour at the terminator      |
//   | c2   | [r, g, b] | [0, 0, 0] | >= 0  | the colour facing away from it    |
//
//   per light: c0 clamp(x) + c1 (1 - |x|) + c2 clamp(-x), x = N.L;
//   F = C (x) (A + sum att Lc (x) that)
//   Math: models::trilight (shading/models.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct Trilight {
  static constexpr const char* kName = "trilight";
  glm::dvec3 c0{1.0};
  glm::dvec3 c1{0.0};
  glm::dvec3 c2{0.0};

  static auto params() {
    using namespace model;
    using M = Trilight;
    return std::tuple{ColourParam<M>{"c0", &M::c0, kNonNegative}, ColourParam<M>{"c1", &M::c1, kNonNegative},
                      ColourParam<M>{"c2", &M::c2, kNonNegative}};
  }
};

}  // namespace xval
