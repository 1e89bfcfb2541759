// Lights prepared for shading, and what one light gives at a surface point.
//
// point / spot:  L = (p_light - p) / d, d = |p_light - p|;
//                att = 1 / (c + l d + q d^2), not computed when (1, 0, 0).
//                A point exactly at the light (d = 0) gets L = 0: no diffuse,
//                no highlight, no NaN. d and L are formed without overflow
//                or underflow of (p_light - p)^2 (towardsLight below).
// spot:          lit iff dot(-L, axis) >= cos(cutoff) (a hard cone).
// directional:   L = -direction, att = 1.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "scene/scene.h"
#include "shading/models.h"

namespace xval {

template <class T> struct PreparedLight {
  enum class Kind { Point, Directional, Spot };
  using V = glm::vec<3, T>;
  Kind kind = Kind::Point;
  V position{0}, direction{0}, color{0};
  T color_luma = 0;  // the YIQ model lights luma only
  bool has_attenuation = false;
  T att_c = 1, att_l = 0, att_q = 0;
  T cos_cutoff = -1;
};

template <class T> struct LightSample {
  glm::vec<3, T> L;  // unit, towards the light (0 at the light itself)
  T att;
  bool lit;  // false outside a spot cone
};

// The unit vector along D = p_light - p and its length d (docs/extremes.md,
// case light_far_1e20). d = sqrt(D.D) fails where D.D leaves the normal
// range of T: in float, D.D overflows for |D| > 1.8e19 (d = inf, L = 0: the
// light vanishes) and is subnormal for |D| < 1.1e-19 (L is then not unit).
// When D.D is a normal number it is used as is (the usual case, unchanged);
// otherwise D is first divided by its largest |component| s:
//   d = s |D / s|,  L = (D / s) / |D / s|,  with 1 <= |D / s| <= sqrt(3).
// D = 0 gives d = 0 and L = 0.
template <class T> void towardsLight(glm::vec<3, T> D, glm::vec<3, T>& L, T& d) {
  const T dd = glm::dot(D, D);
  if (dd >= std::numeric_limits<T>::min() && dd <= std::numeric_limits<T>::max()) {
    d = std::sqrt(dd);
    L = D / d;
    return;
  }
  const T s = std::max(std::abs(D.x), std::max(std::abs(D.y), std::abs(D.z)));
  if (!(s > T(0)) || !(s <= std::numeric_limits<T>::max())) {  // 0, or not finite
    d = s;
    L = glm::vec<3, T>(0);
    return;
  }
  const glm::vec<3, T> u = D / s;
  const T lu = std::sqrt(glm::dot(u, u));
  d = s * lu;
  L = u / lu;
}

// Whether towardsLight<float> can take its rescaling path (D.D not a normal
// float) for a light at `light` and a point of the box [lo, hi] (the same
// coordinates): no when every point of the box is at least
// 1e-4 (1 + m) from the light, m the largest |coordinate| of the light and
// the box, and at most 1e15 from it. The float D of such a point, rounding of
// its position and of its interpolation across a triangle included (relative
// errors near 1e-7 of m), then has D.D between 1e-8 and 1e30 (x 1.001),
// inside float's normal range [1.2e-38, 3.4e38]. Non-finite input: yes.
inline bool towardsLightMayRescale(glm::dvec3 light, glm::dvec3 lo, glm::dvec3 hi) {
  const glm::dvec3 nearest = glm::clamp(light, lo, hi);
  const glm::dvec3 farthest = glm::max(glm::abs(light - lo), glm::abs(light - hi));
  const double m = std::max({std::abs(light.x), std::abs(light.y), std::abs(light.z), std::abs(lo.x),
                             std::abs(lo.y), std::abs(lo.z), std::abs(hi.x), std::abs(hi.y), std::abs(hi.z)});
  const double min_d = glm::length(light - nearest), max_d = glm::length(farthest);
  return !(std::isfinite(m) && min_d >= 1e-4 * (1.0 + m) && max_d <= 1e15);
}

template <class T>
LightSample<T> sampleLight(const PreparedLight<T>& l, glm::vec<3, T> p) {
  using K = typename PreparedLight<T>::Kind;
  if (l.kind == K::Directional) return {-l.direction, T(1), true};
  LightSample<T> s{glm::vec<3, T>(0), T(1), true};
  T dist;
  towardsLight(l.position - p, s.L, dist);
  if (l.has_attenuation) s.att = T(1) / (l.att_c + l.att_l * dist + l.att_q * dist * dist);
  if (l.kind == K::Spot) s.lit = glm::dot(-s.L, l.direction) >= l.cos_cutoff;
  return s;
}

// Splits the scene's lights into the summed ambient colour and the rest.
// Light positions are stored relative to `origin` (subtracted in double,
// then rounded to T), the origin of the shading coordinates (shader.h).
template <class T>
void prepareLights(const std::vector<Light>& lights, glm::vec<3, T>& ambient,
                   std::vector<PreparedLight<T>>& out, glm::dvec3 origin = glm::dvec3(0)) {
  using V = glm::vec<3, T>;
  using K = typename PreparedLight<T>::Kind;
  ambient = V(0);
  for (const Light& light : lights) {
    PreparedLight<T> pl;
    if (auto* a = std::get_if<AmbientLight>(&light)) {
      ambient += V(a->color);
      continue;
    }
    auto set_att = [&pl](const Attenuation& a) {
      pl.has_attenuation = !a.isNone();
      pl.att_c = T(a.constant);
      pl.att_l = T(a.linear);
      pl.att_q = T(a.quadratic);
    };
    if (auto* p = std::get_if<PointLight>(&light)) {
      pl.kind = K::Point;
      pl.position = V(p->position - origin);
      pl.color = V(p->color);
      set_att(p->attenuation);
    } else if (auto* d = std::get_if<DirectionalLight>(&light)) {
      pl.kind = K::Directional;
      pl.direction = V(glm::normalize(d->direction));
      pl.color = V(d->color);
    } else if (auto* s = std::get_if<SpotLight>(&light)) {
      pl.kind = K::Spot;
      pl.position = V(s->position - origin);
      pl.direction = V(glm::normalize(s->direction));
      pl.color = V(s->color);
      pl.cos_cutoff = T(std::cos(s->cutoff_deg * std::numbers::pi / 180.0));
      set_att(s->attenuation);
    }
    pl.color_luma = models::lightLuma(pl.color);
    out.push_back(pl);
  }
}

// The luma-only mode's lights (colour/luma_only.h, step 1): every light,
// ambient included, with its colour replaced by the grey of its luma in
// space s (white stays white), in double. Every backend shades a
// luma-only material with these.
inline std::vector<Light> greyLights(const std::vector<Light>& lights, LumaSpace s) {
  std::vector<Light> out = lights;
  for (auto& l : out)
    std::visit([s](auto& x) { x.color = glm::dvec3(luma_only::lightLuma(s, x.color)); }, l);
  return out;
}

}  // namespace xval
