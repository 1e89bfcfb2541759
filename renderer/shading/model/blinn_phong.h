// Lighting model `blinn_phong`: Blinn's half-vector highlight (J. F. Blinn,
// "Models of light reflection for computer synthesized pictures", SIGGRAPH
// 1977) with classic_phong's paper-variant ambient and diffuse terms
// (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name      | type  | default | range | meaning                               |
//   | ka        | float | 1       | >= 0  | ambient weight                        |
//   | kd        | float | 1       | >= 0  | diffuse weight                        |
//   | ks        | float | 1       | >= 0  | specular weight (0: no specular term) |
//   | shininess | float | 55      | >= 0  | specular exponent n                   |
//
//   H = normalize(L + V) (0 where L + V = 0);
//   F = C (x) (ka A + kd sum att Lc clamp(N.L)) + ks sum att Lc clamp(N.H)^n
//   The highlight is not gated by N.L, as classic_phong's R.V is not.
//   Math: models::halfVector, models::phongSpecular (shading/models.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct BlinnPhong {
  static constexpr const char* kName = "blinn_phong";
  double ka = 1.0, kd = 1.0, ks = 1.0;
  double shininess = 55.0;

  static auto params() {
    using namespace model;
    using M = BlinnPhong;
    return std::tuple{NumberParam<M>{"ka", &M::ka, Unit::Weight, kNonNegative, Role::Coefficient},
                      NumberParam<M>{"kd", &M::kd, Unit::Weight, kNonNegative, Role::Coefficient},
                      NumberParam<M>{"ks", &M::ks, Unit::Weight, kNonNegative, Role::Specular},
                      NumberParam<M>{"shininess", &M::shininess, Unit::Exponent, kNonNegative, Role::None}};
  }
};

}  // namespace xval
