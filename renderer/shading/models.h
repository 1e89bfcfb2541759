// The lighting models as pure functions (docs/models.md).
//
// Templated on the scalar T (float for the fast path, double for the
// reference path). x = N.L throughout; all vectors unit length.
// clamp0(x) = max(x, 0); saturate(x) = min(max(x, 0), 1). Both map NaN to 0
// (the comparisons are written so), which keeps a NaN from propagating.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

#include "colour/yiq.h"

namespace xval::models {

template <class T> using vec3 = glm::vec<3, T>;

template <class T> constexpr T clamp0(T x) { return x > T(0) ? x : T(0); }
template <class T> constexpr T saturate(T x) { return x > T(0) ? (x < T(1) ? x : T(1)) : T(0); }
template <class T> vec3<T> saturate(vec3<T> c) {
  return {saturate(c.x), saturate(c.y), saturate(c.z)};
}

// ---- Phong terms (paper eq. 1-2; seed 003 eq. 8.2-8.3) -----------------
// R = 2 (N.L) N - L, the mirror direction of L about N.
template <class T> vec3<T> reflect(vec3<T> n, vec3<T> l, T ndotl) {
  return T(2) * ndotl * n - l;
}
// S = clamp(R.V)^n. n = 0 gives 1 everywhere (pow(0, 0) = 1 by the C
// standard; HLSL leaves it undefined): a constant highlight, by choice.
// The listing's form, from R.V; the shader uses the form below.
template <class T> T phongSpecular(T rdotv, T shininess) {
  return std::pow(clamp0(rdotv), shininess);
}
// The same S = clamp(R.V)^n from the unit vectors R and V, without the
// cancellation in 1 - R.V (docs/extremes.md, case specular_n1e6):
//   h = 1 - R.V = |R - V|^2 / 2   (for |R| = |V| = 1),
//   S = (1 - h)^n = exp(n log1p(-h)).
// At high n the whole highlight lies where 1 - R.V is tiny (n = 1e6: below
// ~1e-5), and R.V rounded to the nearest float (ulp 6e-8 near 1) moves S by
// up to a factor exp(1e6 x 6e-8) = 1.06 from one ulp to the next. R - V is
// formed from exact differences of nearly equal components, so h keeps
// float's relative precision; the rounding of |R| and |V| to 1 enters h
// only as a relative error of the same size. Special values as above:
// R.V <= 0 or NaN gives 0^n = 0 (n > 0) or 1 (n = 0, pow(0, 0) = 1); R = 0
// (a light at the shaded point, L = 0) has R.V = 0.
// Outside the highlight S is negligible and not evaluated: log1p(-h) <= -h,
// so S <= exp(-n h), and where n h > kSpecularCutoff<T> that bound is below
// 2^-25 in float (half an ulp of 1) and 2^-54 in double: S is returned as 0,
// an absolute change of less than that bound (x ks x the light's weight in
// the model). This skips log1p and exp on most of a surface (n = 55:
// wherever R.V < ~0.69).
template <class T> inline constexpr T kSpecularCutoff = T(0);
template <> inline constexpr float kSpecularCutoff<float> = 17.32868f;   // 25 ln 2
template <> inline constexpr double kSpecularCutoff<double> = 37.42994;  // 54 ln 2
template <class T> T phongSpecular(vec3<T> r, vec3<T> v, T shininess) {
  const T rdotv = glm::dot(r, v);
  if (!(rdotv > T(0)) || shininess == T(0)) return shininess == T(0) ? T(1) : T(0);
  const vec3<T> e = r - v;
  const T h = T(0.5) * glm::dot(e, e);
  if (!(h < T(1))) return T(0);  // R.V within rounding of 0: clamp(R.V) = 0
  if (shininess * h > kSpecularCutoff<T>) return T(0);  // S < 2^-25 (float), 2^-54 (double)
  return std::exp(shininess * std::log1p(-h));
}

// ---- Forsyth's family (seed 002), result per unit light colour ---------
template <class T> T lambert(T x) { return clamp0(x); }
// clamp(x + f) / (1 + f), f in [0, 1]
template <class T> T wrapAround(T x, T f) { return clamp0(x + f) / (T(1) + f); }
// lerp(c2, c0, (x + 1) / 2)
template <class T> vec3<T> hemispherical(T x, vec3<T> c0, vec3<T> c2) {
  return c2 + (c0 - c2) * ((x + T(1)) * T(0.5));
}
// c0 clamp(x) + c2 clamp(-x)
template <class T> vec3<T> biDirectional(T x, vec3<T> c0, vec3<T> c2) {
  return c0 * clamp0(x) + c2 * clamp0(-x);
}
// c0 clamp(x) + c1 (1 - |x|) + c2 clamp(-x)
template <class T> vec3<T> trilight(T x, vec3<T> c0, vec3<T> c1, vec3<T> c2) {
  return c0 * clamp0(x) + c1 * (T(1) - std::abs(x)) + c2 * clamp0(-x);
}

// ---- YIQ (paper eq. 4-5 and the Table 1 listing) ------------------------
// The matrices and conversions are colour/yiq.h's.
using colour::kRgbToYiq;
using colour::kYiqToRgb;
using colour::luma;
using colour::rgbToYiq;
using colour::yiqToRgb;
// A light's intensity for the YIQ model: its luma, normalised so that white
// (1,1,1) is exactly 1 (the listing's luma row sums to 1.00000001).
template <class T> T lightLuma(vec3<T> c) {
  constexpr double white = kRgbToYiq[0][0] + kRgbToYiq[0][1] + kRgbToYiq[0][2];
  return T(kRgbToYiq[0][0] / white) * c.x + T(kRgbToYiq[0][1] / white) * c.y +
         T(kRgbToYiq[0][2] / white) * c.z;
}

// The listing's LumaPhongDiffuse, literally: RGB -> YIQ, Y' = Y Dl + S - off,
// YIQ -> RGB. Dl and S are the listing's Diffuse and Specular. Unsaturated.
template <class T> vec3<T> yiqLumaListing(vec3<T> c, T dl, T s, T offset) {
  vec3<T> yiq = rgbToYiq(c);
  yiq.x = yiq.x * dl + s - offset;
  return yiqToRgb(yiq);
}
// The same, reduced: the first column of YIQ->RGB is exactly (1,1,1), so
// the round trip changes every channel by Y' - Y:
//   F = C + (Y (Dl - 1) + S - off) (1,1,1)
// One dot product instead of two matrix products (used by the renderer).
template <class T> vec3<T> yiqLuma(vec3<T> c, T dl, T s, T offset) {
  T dy = luma(c) * (dl - T(1)) + s - offset;
  return c + vec3<T>(dy);
}

}  // namespace xval::models
