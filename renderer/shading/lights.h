// Lights prepared for shading, and what one light gives at a surface point.
//
// point / spot:  L = (p_light - p) / d, d = |p_light - p|;
//                att = 1 / (c + l d + q d^2), not computed when (1, 0, 0).
//                A point exactly at the light (d = 0) gets L = 0: no diffuse,
//                no highlight, no NaN.
// spot:          lit iff dot(-L, axis) >= cos(cutoff) (a hard cone).
// directional:   L = -direction, att = 1.
#pragma once

#include <glm/glm.hpp>

#include <cmath>
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

template <class T>
LightSample<T> sampleLight(const PreparedLight<T>& l, glm::vec<3, T> p) {
  using K = typename PreparedLight<T>::Kind;
  if (l.kind == K::Directional) return {-l.direction, T(1), true};
  glm::vec<3, T> d = l.position - p;
  T dist = glm::length(d);
  LightSample<T> s{dist > T(0) ? d / dist : glm::vec<3, T>(0), T(1), true};
  if (l.has_attenuation) s.att = T(1) / (l.att_c + l.att_l * dist + l.att_q * dist * dist);
  if (l.kind == K::Spot) s.lit = glm::dot(-s.L, l.direction) >= l.cos_cutoff;
  return s;
}

// Splits the scene's lights into the summed ambient colour and the rest.
template <class T>
void prepareLights(const std::vector<Light>& lights, glm::vec<3, T>& ambient,
                   std::vector<PreparedLight<T>>& out) {
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
      pl.position = V(p->position);
      pl.color = V(p->color);
      set_att(p->attenuation);
    } else if (auto* d = std::get_if<DirectionalLight>(&light)) {
      pl.kind = K::Directional;
      pl.direction = V(glm::normalize(d->direction));
      pl.color = V(d->color);
    } else if (auto* s = std::get_if<SpotLight>(&light)) {
      pl.kind = K::Spot;
      pl.position = V(s->position);
      pl.direction = V(glm::normalize(s->direction));
      pl.color = V(s->color);
      pl.cos_cutoff = T(std::cos(s->cutoff_deg * 3.14159265358979323846 / 180.0));
      set_att(s->attenuation);
    }
    pl.color_luma = models::lightLuma(pl.color);
    out.push_back(pl);
  }
}

}  // namespace xval
