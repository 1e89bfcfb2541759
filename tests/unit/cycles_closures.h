// Blender 3.4 Cycles' closures as written in its source (tag v3.4.0,
// kernel/closure/bsdf_microfacet.h and bsdf_oren_nayar.h): each returns
// Cycles' eval, its BSDF x N.L, in Cycles' own units (Lambert: N.L / pi).
// The tests compare our models and the native tier's conversions with
// these, not with our own math.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace xval::test {

// bsdf_microfacet_{ggx,beckmann}_eval, isotropic (tan^2 from 1 - cos^2; G1
// from 1 / a); alpha the closure's (the node's Roughness squared).
inline double cyclesGlossyEval(bool ggx, double alpha, glm::dvec3 n, glm::dvec3 l, glm::dvec3 v) {
  constexpr double pi = std::numbers::pi;
  const double cosNO = glm::dot(n, v), cosNI = glm::dot(n, l);
  if (!(cosNO > 0 && cosNI > 0)) return 0;
  const glm::dvec3 m = glm::normalize(l + v);
  const double c = glm::dot(n, m), t2 = (1 - c * c) / (c * c), a2 = alpha * alpha;
  double D, G1o, G1i;
  if (ggx) {
    D = a2 / (pi * c * c * c * c * (a2 + t2) * (a2 + t2));
    auto g1 = [&](double x) { return 2 / (1 + std::sqrt(1 + a2 * (1 - x * x) / (x * x))); };
    G1o = g1(cosNO), G1i = g1(cosNI);
  } else {
    D = std::exp(-t2 / a2) / (pi * a2 * c * c * c * c);
    auto g1 = [&](double x) {
      const double invA = alpha * std::sqrt((1 - x * x) / (x * x));
      if (invA < 0.625) return 1.0;
      const double a = 1 / invA;
      return (3.535 * a + 2.181 * a * a) / (1 + 2.276 * a + 2.577 * a * a);
    };
    G1o = g1(cosNO), G1i = g1(cosNI);
  }
  return G1o * G1i * D * 0.25 / cosNO;
}

// bsdf_oren_nayar_setup + bsdf_oren_nayar_get_intensity; roughness the
// Diffuse BSDF's Roughness socket (clamped to [0, 1] there).
inline double cyclesOrenNayarEval(double roughness, glm::dvec3 n, glm::dvec3 l, glm::dvec3 v) {
  constexpr double pi = std::numbers::pi;
  if (!(glm::dot(n, l) > 0)) return 0;
  const double sigma = std::clamp(roughness, 0.0, 1.0);
  const double div = 1.0 / (pi + ((3.0 * pi - 4.0) / 6.0) * sigma);
  const double a = div, b = sigma * div;
  const double nl = std::max(glm::dot(n, l), 0.0), nv = std::max(glm::dot(n, v), 0.0);
  double t = glm::dot(l, v) - nl * nv;
  if (t > 0) t /= std::max(nl, nv);
  return nl * (a + b * t);
}

}  // namespace xval::test
