// Lighting model `lambert`: Forsyth's family (seed 002), Lambert's term
// (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name | type      | default   | range | meaning                     |
//   | c0   | [r, g, b] | [1, 1, 1] | >= 0  | the colour facing the light |
//
//   per light: c0 clamp(x), x = N.L;  F = C (x) (A + sum att Lc (x) that)
//   Math: models::lambert (shading/models.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct Lambert {
  static constexpr const char* kName = "lambert";
  glm::dvec3 c0{1.0};

  static auto params() {
    using namespace model;
    return std::tuple{ColourParam<Lambert>{"c0", &Lambert::c0, kNonNegative}};
  }
};

}  // namespace xval
