// Lighting model `cook_torrance`: a microfacet specular term (Cook &
// Torrance 1982; Walter et al. 2007) over a Lambert diffuse term
// (docs/models.md, "Cook-Torrance").
//
//   Parameters (scene file: material.model)
//   | name         | type   | default | range      | meaning                                 |
//   | distribution | string | "ggx"   | "ggx", "beckmann" | the microfacet distribution D    |
//   | geometry     | string | "smith" | "smith", "cook_torrance" | G: separable Smith G1(L) G1(V) with D's own G1, or the 1982 V-groove min(1, 2 nh nv/vh, 2 nh nl/vh) |
//   | fresnel      | string | "none"  | "none", "schlick" | F = 1, or Schlick's f0 + (1 - f0)(1 - V.H)^5 |
//   | f0           | float  | 0.04    | [0, 1]     | Schlick's reflectance at normal incidence |
//   | roughness    | float  | 0.25    | (0, 1]     | alpha, D's width (Beckmann: the rms slope m); Cycles' Roughness socket r has alpha = r^2 |
//   | kd           | float  | 1       | >= 0       | diffuse weight                           |
//   | ks           | float  | 1       | >= 0       | specular weight (0: no specular term)   |
//
//   F = C (x) (A + kd sum att Lc clamp(N.L)) + ks sum att Lc S,
//   S = pi F D G / (4 N.V)   (pi x the BRDF F D G / (4 N.L N.V) x N.L)
//   Math: models::cookTorranceSpecular (shading/models.h).
//   The defaults are Cycles' Glossy BSDF (GGX, Roughness 0.5) over its
//   Diffuse BSDF, for a point light of power 4 pi^2 Lc (docs/models.md).
#pragma once

#include "shading/model/params.h"
#include "shading/model/microfacet.h"

namespace xval {

struct CookTorrance {
  static constexpr const char* kName = "cook_torrance";
  models::MicrofacetD distribution = models::MicrofacetD::Ggx;
  models::MicrofacetG geometry = models::MicrofacetG::Smith;
  models::MicrofacetF fresnel = models::MicrofacetF::None;
  double f0 = 0.04;
  double roughness = 0.25;
  double kd = 1.0, ks = 1.0;

  // The largest S (above) per unit ks, over every geometry (the precision
  // limits' bound, scene_file/precision_limits.cpp: it multiplies ks). With
  // alpha <= 1 and F <= 1: D <= 1.5 / (pi alpha^2) (GGX: 1 / (pi alpha^2) at
  // N.H = 1; Beckmann: the same for alpha^2 <= 1/2, 4/e / (pi alpha^2) at
  // alpha = 1); G / N.V <= 7.1 / alpha (Smith: G1(N.L) <= 1 and G1(x)/x <=
  // 2 / alpha for GGX, <= 7.1 / alpha for Beckmann's approximation) or
  // <= 2^11 (V-groove, with V.H >= 2^-10: models::vGrooveGOverNv).
  // The parameter specularGain() depends on (named in the precision
  // limits' message when the gain, not ks, is what exceeds them).
  static constexpr const char* kSpecularGainParam = "roughness";
  double specularGain() const {
    const double a = roughness;
    const double g_over_nv = geometry == models::MicrofacetG::Smith ? 7.1 / a : 2048.0;
    return 0.25 * 1.5 / (a * a) * g_over_nv;
  }

  static auto params() {
    using namespace model;
    using M = CookTorrance;
    using D = models::MicrofacetD;
    using G = models::MicrofacetG;
    using F = models::MicrofacetF;
    return std::tuple{
        ChoiceParam<M, D, 2>{"distribution", &M::distribution, {{{"ggx", D::Ggx}, {"beckmann", D::Beckmann}}}},
        ChoiceParam<M, G, 2>{"geometry", &M::geometry, {{{"smith", G::Smith}, {"cook_torrance", G::VGroove}}}},
        ChoiceParam<M, F, 2>{"fresnel", &M::fresnel, {{{"none", F::None}, {"schlick", F::Schlick}}}},
        NumberParam<M>{"f0", &M::f0, Unit::Weight, kUnitInterval, Role::None},
        NumberParam<M>{"roughness", &M::roughness, Unit::Weight, ParamRange{0.0, 1.0, true, false}, Role::None},
        NumberParam<M>{"kd", &M::kd, Unit::Weight, kNonNegative, Role::Coefficient},
        NumberParam<M>{"ks", &M::ks, Unit::Weight, kNonNegative, Role::Specular}};
  }
};

}  // namespace xval
