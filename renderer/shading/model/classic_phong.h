// Lighting model `classic_phong`: Phong's model, two variants (docs/models.md).
//
//   Parameters (scene file: material.model)
//   | name      | type   | default | range   | meaning                                   |
//   | variant   | string | "paper" | "paper", "course" | which formula, below            |
//   | ka        | float  | 1       | >= 0    | ambient weight                            |
//   | kd        | float  | 1       | >= 0    | diffuse weight                            |
//   | ks        | float  | 1       | >= 0    | specular weight (0: no specular term)     |
//   | shininess | float  | 55      | >= 0    | specular exponent n                       |
//
//   variant paper (paper eq. 3, seed 003):
//     F = C (x) (ka A + kd sum att Lc clamp(N.L)) + ks sum att Lc clamp(R.V)^n
//   variant course (seed 004, specular tinted, per-light ambient):
//     F = C (x) (ka A + sum att Lc (ka + [lit] (kd clamp(N.L) + ks clamp(R.V)^n)))
//   Math: models::phongSpecular (shading/models.h); summed over the lights
//   by Shader (shading/shader.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct ClassicPhong {
  static constexpr const char* kName = "classic_phong";
  enum class Variant { Paper, Course };
  Variant variant = Variant::Paper;
  double ka = 1.0, kd = 1.0, ks = 1.0;
  double shininess = 55.0;

  static auto params() {
    using namespace model;
    using M = ClassicPhong;
    return std::tuple{
        ChoiceParam<M, Variant, 2>{"variant", &M::variant, {{{"paper", Variant::Paper}, {"course", Variant::Course}}}},
        NumberParam<M>{"ka", &M::ka, Unit::Weight, kNonNegative, Role::Coefficient},
        NumberParam<M>{"kd", &M::kd, Unit::Weight, kNonNegative, Role::Coefficient},
        NumberParam<M>{"ks", &M::ks, Unit::Weight, kNonNegative, Role::Specular},
        NumberParam<M>{"shininess", &M::shininess, Unit::Exponent, kNonNegative, Role::None}};
  }
};

}  // namespace xval
