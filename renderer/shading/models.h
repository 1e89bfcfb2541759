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
#include "shading/model/microfacet.h"

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

// ---- Cook-Torrance (cook_torrance; docs/models.md) -----------------------
// A microfacet specular term. Per light, in the convention of the other
// models (Lambert's term is C Lc clamp(N.L): pi x the BRDF C/pi x N.L),
// the specular term is pi x the BRDF x N.L:
//   S = pi F D G / (4 nl nv) x nl = pi F D G / (4 nv),
// nl = N.L, nv = N.V, H = normalize(L + V), nh = N.H, vh = V.H, alpha the
// distribution's width (Beckmann: the rms slope m; GGX: alpha; NOT Cycles'
// Roughness socket, whose alpha is Roughness^2).
//   D Beckmann = exp(-tan^2 / alpha^2) / (pi alpha^2 nh^4)
//   D GGX      = alpha^2 / (pi nh^4 (alpha^2 + tan^2)^2),  tan^2 = tan^2 of angle(N, H)
// both normalised: the integral of D nh over the hemisphere is 1.
//   G V-groove (Cook & Torrance 1982) = min(1, 2 nh nv / vh, 2 nh nl / vh)
//   G Smith    = G1(nl) G1(nv), separable, with the distribution's own G1:
//     GGX      G1(x) = 2 x / (x + sqrt(x^2 + alpha^2 (1 - x^2)))   (exact)
//     Beckmann a = x / (alpha sqrt(1 - x^2)); G1 = 1 for a >= 1.6, else
//              (3.535 a + 2.181 a^2) / (1 + 2.276 a + 2.577 a^2)
//              (Walter et al. 2007's rational approximation, as Cycles)
//   F Schlick  = f0 + (1 - f0) (1 - vh)^5;  none: F = 1.
//
// Numerics. The BRDF's 1 / (nl nv) is never formed: its nl cancels against
// the cosine of the light (S above), and what divides by nv is formed as
// G / nv, finite as nv -> 0:
//   Smith:    G1(nv) / nv = 2 / (nv + sqrt(nv^2 + alpha^2 s_v^2)) <= 2 / alpha
//             (GGX), (3.535 + 2.181 a) / ((1 + 2.276 a + 2.577 a^2) alpha s_v)
//             <= 3.6 / alpha (Beckmann, a < 1.6) or 1 / nv < 1.2 / alpha
//             (a >= 1.6);
//   V-groove: G / nv = min(1 / nv, 2 nh / vh, 2 nh nl / (vh nv)), which
//             grows without bound as L -> -V with both at grazing angles
//             (vh = cos(angle(L, V) / 2) -> 0, nh anything): there vh is
//             taken as max(vh, 2^-10), so G / nv <= 2^11. This departs from
//             the 1982 formula only where angle(L, V) > 179.89 degrees, and
//             keeps S bounded (CookTorrance::specularGain), which float's
//             rounding of a vh near 0 would otherwise not.
// S is 0 unless nl > 0, nv > 0 (strict, as Cycles) and vh > 0 (vh = |L + V| / 2,
// 0 only for L = -V). sin^2 and tan^2 are formed from cross products
// (|N x H|^2 = 1 - nh^2 for unit vectors), not as 1 - nh^2, which cancels
// near the highlight's centre where tan^2 ~ alpha^2 (alpha = 0.01 in float:
// a relative error of 1e-3 in the exponent's argument). Beckmann's D is 0
// where its exponential underflows (the nh^4 below it could be 0 too).
// The choices of D, G and F: shading/model/microfacet.h.

// D from c = nh > 0 and s2 = |N x H|^2 = sin^2 of angle(N, H).
template <class T> T microfacetD(MicrofacetD d, T c, T s2, T alpha) {
  constexpr T pi = T(3.14159265358979323846);
  const T a2 = alpha * alpha, c2 = c * c;
  if (d == MicrofacetD::Beckmann) {
    const T e = std::exp(-s2 / (c2 * a2));
    return e > T(0) ? e / (pi * a2 * c2 * c2) : T(0);
  }
  // alpha^2 / (pi (c^2 alpha^2 + s^2)^2): c^4 (alpha^2 + tan^2)^2 with
  // tan^2 = s^2 / c^2, formed as (alpha / q)^2 / pi: at the peak (s = 0,
  // c = 1) q = alpha^2, and q^2 = alpha^4 underflows float for alpha below
  // ~1e-11 (to 0 below 6e-12, within the alpha float accepts: a^2 / 0 =
  // inf; case ct_ggx_alpha_min), while alpha / q <= 1 / (alpha c^2) stays
  // in range down to the smallest alpha the precision limits let through.
  const T q = c2 * a2 + s2, r = alpha / q;
  return r * r / pi;
}
// Smith's G1(x) / x for x = N.X > 0, s2 = |N x X|^2.
template <class T> T smithG1OverCos(MicrofacetD d, T x, T s2, T alpha) {
  if (d == MicrofacetD::Ggx) return T(2) / (x + std::sqrt(x * x + alpha * alpha * s2));
  const T as = alpha * std::sqrt(s2);  // x / a
  if (x >= T(1.6) * as) return T(1) / x;
  const T a = x / as;
  return (T(3.535) + T(2.181) * a) / ((T(1) + T(2.276) * a + T(2.577) * a * a) * as);
}
// G / nv, V-groove (vh at least 2^-10, above).
template <class T> inline constexpr T kVGrooveMinVh = T(1.0 / 1024.0);
template <class T> T vGrooveGOverNv(T nl, T nv, T nh, T vh) {
  const T k = T(2) * nh / std::max(vh, kVGrooveMinVh<T>);
  return std::min(T(1) / nv, std::min(k, k * nl / nv));
}
template <class T> T schlickFresnel(T f0, T vh) {
  const T m = T(1) - vh, m2 = m * m;
  return f0 + (T(1) - f0) * (m2 * m2 * m);
}
// S = pi F D G / (4 nv) for unit n, l, v (above).
template <class T>
T cookTorranceSpecular(vec3<T> n, vec3<T> l, vec3<T> v, MicrofacetD d, MicrofacetG g, MicrofacetF f, T alpha,
                       T f0) {
  constexpr T pi = T(3.14159265358979323846);
  const T nl = glm::dot(n, l), nv = glm::dot(n, v);
  if (!(nl > T(0)) || !(nv > T(0))) return T(0);
  const vec3<T> sum = l + v;
  const T len = glm::length(sum);
  if (!(len > T(0))) return T(0);
  const vec3<T> h = sum / len;
  // V.H = (1 + L.V) / |L + V| = |L + V| / 2 for unit L and V: from the
  // length, not as dot(v, h). Near L = -V (both grazing, on opposite
  // sides) H is nearly orthogonal to V and dot(v, h) sums terms of size 1
  // that cancel to V.H ~ 1e-4, each carrying H's rounding error divided by
  // |L + V| (in float ~6e-8 / 3e-4): V.H came out as noise (case
  // ct_beckmann_vgroove_schlick_grazing, 45000/65535 float vs double
  // through the V-groove's 2 N.H / V.H), while |L + V| keeps float's
  // relative precision.
  const T nh = glm::dot(n, h), vh = T(0.5) * len;
  if (!(nh > T(0))) return T(0);
  const vec3<T> nxh = glm::cross(n, h);
  const T dist = microfacetD(d, nh, glm::dot(nxh, nxh), alpha);
  if (!(dist > T(0))) return T(0);
  T g_over_nv;
  if (g == MicrofacetG::Smith) {
    const vec3<T> nxl = glm::cross(n, l), nxv = glm::cross(n, v);
    g_over_nv = nl * smithG1OverCos(d, nl, glm::dot(nxl, nxl), alpha) *
                smithG1OverCos(d, nv, glm::dot(nxv, nxv), alpha);
  } else {
    g_over_nv = vGrooveGOverNv(nl, nv, nh, vh);
  }
  const T fres = f == MicrofacetF::Schlick ? schlickFresnel(f0, vh) : T(1);
  return pi * fres * dist * g_over_nv * T(0.25);
}

}  // namespace xval::models
