// Lighting model `minnaert`: Minnaert's limb-darkening law (M. Minnaert,
// "The reciprocity principle in lunar photometry", ApJ 93:403, 1941), in
// the lambert model's form (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name | type  | default | range | meaning                                  |
//   | kd   | float | 1       | >= 0  | diffuse weight                           |
//   | k    | float | 1       | > 0   | Minnaert exponent (1: Lambert; > 1 darkens the limb) |
//
//   per light: M = clamp(N.L)^k clamp(N.V)^(k-1);  F = C (x) (A + kd sum att Lc M)
//   M = 0 where N.L <= 0; where N.V <= 0, M = 0 except for k = 1 (x^0 = 1,
//   so that k = 1 is Lambert everywhere; for k < 1 the factor would be
//   infinite there, and is taken as 0: the point is not seen).
//   Math: models::minnaert (shading/models.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct Minnaert {
  static constexpr const char* kName = "minnaert";
  double kd = 1.0;
  double k = 1.0;

  static auto params() {
    using namespace model;
    using M = Minnaert;
    return std::tuple{NumberParam<M>{"kd", &M::kd, Unit::Weight, kNonNegative, Role::Coefficient},
                      NumberParam<M>{"k", &M::k, Unit::Exponent, ParamRange{0.0, 1e300, true, false}, Role::None}};
  }
};

}  // namespace xval
