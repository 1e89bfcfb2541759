// Lighting model `wrap_around`: Forsyth's family (seed 002), the light
// wrapped past the terminator (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name   | type      | default   | range  | meaning                              |
//   | c0     | [r, g, b] | [1, 1, 1] | >= 0   | the colour facing the light          |
//   | factor | float     | 0.5       | [0, 1] | how far past N.L = 0 the light wraps |
//
//   per light: c0 clamp(x + factor) / (1 + factor), x = N.L;
//   F = C (x) (A + sum att Lc (x) that)
//   Math: models::wrapAround (shading/models.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct WrapAround {
  static constexpr const char* kName = "wrap_around";
  glm::dvec3 c0{1.0};
  double factor = 0.5;

  static auto params() {
    using namespace model;
    using M = WrapAround;
    return std::tuple{ColourParam<M>{"c0", &M::c0, kNonNegative},
                      NumberParam<M>{"factor", &M::factor, Unit::Weight, kUnitInterval, Role::None}};
  }
};

}  // namespace xval
