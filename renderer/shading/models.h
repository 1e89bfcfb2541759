// The lighting models as pure functions (docs/models.md).
//
// Templated on the scalar T (float for the fast path, double for the
// reference path). x = N.L throughout; all vectors unit length.
// clamp0(x) = max(x, 0); saturate(x) = min(max(x, 0), 1). Both map NaN to 0
// (the comparisons are written so), which keeps a NaN from propagating.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
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

// ---- Minnaert, Blinn-Phong, Oren-Nayar (issue #33), per unit light colour
// Minnaert (ApJ 93:403, 1941): M = clamp(x)^k clamp(y)^(k-1), y = N.V.
// x <= 0 (or NaN) gives 0. y <= 0 gives clamp(x) for k = 1 (pow(0, 0) = 1:
// k = 1 is Lambert everywhere, bit for bit, since pow(x, 1) = x) and 0 for
// any other k (for k < 1 the power of 0 would be infinite: the point is
// not seen, and the term is taken as 0). For k < 1 and y > 0 the factor
// y^(k-1) grows without bound towards the silhouette (y -> 0): it
// overflows to +inf where y^(k-1) exceeds the precision's range, and the
// final saturate takes C (x) inf to 1 where C > 0 (the limit).
// Numerics: two pow calls, each correctly rounded to within an ulp or so.
template <class T> T minnaert(T x, T y, T k) {
  if (!(x > T(0))) return T(0);
  if (k == T(1)) return x;
  if (!(y > T(0))) return T(0);
  return std::pow(x, k) * std::pow(y, k - T(1));
}

// Blinn's half vector H = normalize(L + V) of unit L and V; 0 where L + V
// is 0 (the light exactly opposite the eye), whose N.H = 0 gives a zero
// highlight (n > 0). The highlight clamp(N.H)^n is phongSpecular(H, N, n)
// (above): from |H - N|, without the cancellation of 1 - N.H at high n.
template <class T> vec3<T> halfVector(vec3<T> l, vec3<T> v) {
  const vec3<T> s = l + v;
  const T len = glm::length(s);
  return len > T(0) ? s / len : vec3<T>(0);
}

// Oren-Nayar, both variants, from x = N.L, y = N.V and lv = L.V:
//   s = lv - x clamp(y)  (= sin(ti) sin(tr) cos(phi_i - phi_r) for unit
//   vectors and y >= 0; y is clamped at 0 as Cycles clamps nv, in both).
// 0 where x <= 0 (or NaN); there max(x, y) >= x > 0, so the division is
// safe. Numerics: s cancels where L.V ~ x y (near the plane of incidence
// at 90 degrees); its absolute error is a few ulps of 1, and the division
// by max(x, y) >= x multiplies it by at most 1/x, which the leading x
// cancels: O's absolute error stays a few ulps.
// The qualitative model (Oren & Nayar 1994), sigma in radians:
//   A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33), B = 0.45 sigma^2 / (sigma^2 + 0.09),
//   O = x (A + B max(s, 0) / max(x, clamp(y))).
struct OrenNayarAB {
  double a, b;
};
inline OrenNayarAB orenNayarQualitativeAB(double sigma) {
  const double s2 = sigma * sigma;
  return {1.0 - 0.5 * s2 / (s2 + 0.33), 0.45 * s2 / (s2 + 0.09)};
}
template <class T> T orenNayarQualitative(T x, T y, T lv, T a, T b) {
  if (!(x > T(0))) return T(0);
  const T yc = clamp0(y);
  const T s = lv - x * yc;
  return x * (a + (s > T(0) ? b * s / std::max(x, yc) : T(0)));
}
// Blender 3.4 Cycles' Diffuse BSDF with roughness sigma > 0
// (bsdf_oren_nayar.h: a = 1 / (pi + (3 pi - 4)/6 sigma), b = sigma a,
// t = s / max(nl, nv) only where s > 0, nl and nv clamped at 0), times pi,
// so that sigma = 0 is Lambert's clamp(N.L) (Cycles' is N.L / pi):
//   a = pi / (pi + 0.904130 sigma), b = sigma a,
//   O = x (a + b t),  t = s / max(x, clamp(y)) where s > 0, else s.
// (3 pi - 4)/6 = 0.9041297... is written exactly below; Cycles rounds it to
// float, as it does sigma.
inline OrenNayarAB orenNayarCyclesAB(double sigma) {
  constexpr double pi = 3.14159265358979323846;
  const double a = pi / (pi + (3.0 * pi - 4.0) / 6.0 * sigma);
  return {a, sigma * a};
}
template <class T> T orenNayarCycles(T x, T y, T lv, T a, T b) {
  if (!(x > T(0))) return T(0);
  const T yc = clamp0(y);
  T t = lv - x * yc;
  if (t > T(0)) t /= std::max(x, yc);
  return x * (a + b * t);
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
