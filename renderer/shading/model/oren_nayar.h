// Lighting model `oren_nayar`: rough diffuse reflection, two variants
// (docs/models.md), in the lambert model's form and normalisation (sigma 0
// is Lambert: kd clamp(N.L)).
//
//   Parameters (scene file: material.model)
//   | name    | type   | default       | range                      | meaning             |
//   | variant | string | "qualitative" | "qualitative", "cycles"    | which formula, below |
//   | kd      | float  | 1             | >= 0                       | diffuse weight      |
//   | sigma   | float  | 0.3           | >= 0                       | roughness, below    |
//
//   x = N.L, y = clamp(N.V) (clamped at 0 as Cycles clamps nv), s = L.V - x y
//   (= sin(ti) sin(tr) cos(phi_i - phi_r)).
//   variant qualitative (M. Oren, S. K. Nayar, "Generalization of Lambert's
//   reflectance model", SIGGRAPH 1994, the qualitative model; sigma the
//   facets' slope deviation in radians):
//     A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33),  B = 0.45 sigma^2 / (sigma^2 + 0.09)
//     O = clamp(x) (A + B max(s, 0) / max(x, y))   (max(0, cos dphi) sin a tan b)
//   variant cycles (Blender 3.4 Cycles' Diffuse BSDF with roughness > 0,
//   intern/cycles/kernel/closure/bsdf_oren_nayar.h; sigma its Roughness):
//     a = pi / (pi + 0.904130 sigma)  (Cycles' 1 / (pi + (3 pi - 4)/6 sigma),
//                                      times pi: Cycles' Lambert is N.L / pi),
//     b = sigma a,  t = s / max(x, y) if s > 0, else s (not clamped)
//     O = clamp(x) (a + b t)
//   per light: F = C (x) (A_amb + kd sum att Lc O)  (A_amb: the ambient sum)
//   O = 0 where N.L <= 0 (then max(x, y) > 0 wherever it divides).
//   Math: models::orenNayarQualitative, models::orenNayarCycles (shading/models.h).
#pragma once

#include "shading/model/params.h"

namespace xval {

struct OrenNayar {
  static constexpr const char* kName = "oren_nayar";
  enum class Variant { Qualitative, Cycles };
  Variant variant = Variant::Qualitative;
  double kd = 1.0;
  double sigma = 0.3;

  static auto params() {
    using namespace model;
    using M = OrenNayar;
    return std::tuple{
        ChoiceParam<M, Variant, 2>{
            "variant", &M::variant, {{{"qualitative", Variant::Qualitative}, {"cycles", Variant::Cycles}}}},
        NumberParam<M>{"kd", &M::kd, Unit::Weight, kNonNegative, Role::Coefficient},
        NumberParam<M>{"sigma", &M::sigma, Unit::Weight, kNonNegative, Role::None}};
  }
};

}  // namespace xval
