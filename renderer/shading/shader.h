// Shader: evaluates the scene's lighting model, summed over its lights, at
// one surface point. The per-model formulas (docs/models.md):
//
//   classic_phong, variant paper (paper eq. 3, seed 003):
//     F = C (x) (ka A + kd sum_l att Lc clamp(N.L)) + ks sum_l att Lc clamp(R.V)^n
//   classic_phong, variant course (seed 004):
//     F = C (x) (ka A + sum_l att Lc (ka + [lit] (kd clamp(N.L) + ks clamp(R.V)^n)))
//   yiq_luma (Table 1 listing; Y = luma of C; Y(Lc) = luma of a light colour,
//   normalised so white is 1; A_Y = Y(A)):
//     Dl = saturate(A_Y + kd sum_l att Y(Lc) saturate(N.L))
//     S  = ks sum_l att Y(Lc) saturate(R.V)^n
//     F  = C + (Y Dl + S - luma_offset - Y) (1,1,1)
//   lambert / wrap_around / hemispherical / bidirectional / trilight:
//     F = C (x) (A + sum_l att Lc (x) forsyth(N.L))
//   minnaert (M = models::minnaert(N.L, N.V, k)):
//     F = C (x) (A + kd sum_l att Lc M)
//   blinn_phong (H = models::halfVector(L, V)):
//     F = C (x) (ka A + kd sum_l att Lc clamp(N.L)) + ks sum_l att Lc clamp(N.H)^n
//   oren_nayar (O = models::orenNayarQualitative or orenNayarCycles of N.L,
//   N.V, L.V):
//     F = C (x) (A + kd sum_l att Lc O)
//   cook_torrance (S = pi F D G / (4 N.V), models::cookTorranceSpecular):
//     F = C (x) (A + kd sum_l att Lc clamp(N.L)) + ks sum_l att Lc S
// A is the summed colour of the ambient lights; [lit] is 0 outside a spot
// cone, where (except course's per-light ambient) a light adds nothing.
// R = 2 (N.L) N - L is not gated by N.L (the listing does not gate it).
// With unitReflection(true) (the scene's normalize_normal false, whose N is
// the interpolated normal, not unit) R = normalize(2 (N.L) N - L), as the
// listing writes it, so that the |R - V| form below gets a unit R.
// The result is unsaturated; the renderer saturates the final pixel colour
// once (the paper's render target did), so the listing's YIQtoRGB saturate
// is that same single saturate.
//
// With the material's luma_only (colour/luma_only.h) the model above is
// evaluated with the grey lights (greyLights) and the grey Y_C (1,1,1), and
// its result G gives the luma Y_out = Y(G) that replaces C's
// (luma_only::withLuma); no model has code of its own for it.
//
// Only what the scene uses is computed: no specular term when ks = 0, no
// attenuation when it is (1,0,0), no texture fetch without a texture (the
// caller passes C).
//
// Shading coordinates: positions (p, and the lights') are relative to an
// origin fixed at construction (default: the world origin); the renderer
// uses the eye (camera-relative shading, docs/extremes.md case offset_1e6):
// world positions and the origin are subtracted in double, so in float a
// surface point keeps float's relative precision of its distance from the
// eye however far both are from the world origin. clamp(R.V)^n is evaluated
// from |R - V| (models::phongSpecular), without cancellation at high n.
#pragma once

#include <glm/glm.hpp>

#include <optional>
#include <vector>

#include "scene/scene.h"
#include "shading/lights.h"
#include "shading/models.h"

namespace xval {

template <class T> class Shader {
 public:
  using V = glm::vec<3, T>;

  // origin: the point shading positions are relative to (see above).
  explicit Shader(const Material& m, const std::vector<Light>& lights,
                  glm::dvec3 origin = glm::dvec3(0))
      : origin_(origin), luma_only_(m.luma_only) {
    prepareLights<T>(luma_only_ ? greyLights(lights, *luma_only_) : lights, ambient_, lights_, origin);
    ambient_luma_ = models::lightLuma(ambient_);
    std::visit([this](const auto& mm) { this->setParams(mm); }, m.model);  // sets kind_
  }

  bool usesSpecular() const { return specular_; }
  // R normalised (see above); off by default (N is unit, so is R).
  void unitReflection(bool on) { unit_reflection_ = on; }
  glm::dvec3 origin() const { return origin_; }
  const std::vector<PreparedLight<T>>& lights() const { return lights_; }
  // A: the summed colour of the ambient lights; A_Y = Y(A) (lightLuma).
  V ambient() const { return ambient_; }
  T ambientLuma() const { return ambient_luma_; }

  // What the model sums over its lights at a point, none of it depending
  // on the surface colour c (by model: classic_phong paper, blinn_phong,
  // cook_torrance: diff and spec; course: diff = ka A + the per-light
  // terms; yiq_luma: dsum and ssum; Forsyth's family: diff = A + the
  // per-light terms; minnaert, oren_nayar: diff). shade() is
  // shadeWith(lit(p, n, v), c), the same operations in the same order, so a
  // caller shading one point with several colours (the precision probes'
  // uv and level steps, render/renderer.cpp) sums the lights once and gets
  // shade()'s result bit for bit.
  struct LightSums {
    V diff{0}, spec{0};
    T dsum = 0, ssum = 0;
  };

  // p: surface point (relative to origin()), n: unit normal, v: unit
  // direction to the eye, c: the surface colour (texture or base colour).
  V shade(V p, V n, V v, V c) const { return shadeWith(lit(p, n, v), c); }

  // The colour from the lights' sums at a point (lit) and its surface
  // colour c; luma_only: the model with the grey Y_C, then Y_C's luma
  // replaced (the header's comment).
  V shadeWith(const LightSums& sums, V c) const {
    if (!luma_only_) return colourOf(sums, c);
    const LumaSpace s = *luma_only_;
    const T y_c = luma_only::surfaceLuma(s, c);
    const T y_out = luma_only::lightLuma(s, colourOf(sums, V(y_c)));
    return luma_only::withLuma(s, c, y_c, y_out);
  }

  // The sums of the material's model (the formulas above) at p, n, v.
  LightSums lit(V p, V n, V v) const {
    return litFrom(n, v, [&](size_t k) { return sampleLight(lights_[k], p); });
  }
  // The same from the lights sampled at p beforehand (sampleLights), for a
  // caller shading one point with several normals (the precision probes'
  // normal turns): the same numbers, sampleLight being a function of the
  // light and p alone.
  void sampleLights(V p, std::vector<LightSample<T>>& out) const {
    out.clear();
    for (const auto& l : lights_) out.push_back(sampleLight(l, p));
  }
  LightSums lit(const std::vector<LightSample<T>>& sampled, V n, V v) const {
    return litFrom(n, v, [&](size_t k) { return sampled[k]; });
  }

 private:
  // lit() with light k's sample from sample(k).
  template <class Sample> LightSums litFrom(V n, V v, const Sample& sample) const {
    using namespace models;
    LightSums out;
    switch (kind_) {
      case ModelId::ClassicPhong: {
        if (course_) {
          V acc = ka_ * ambient_;
          for (size_t k = 0; k < lights_.size(); ++k) {
            const PreparedLight<T>& l = lights_[k];
            LightSample<T> s = sample(k);
            V w = s.att * l.color;
            T term = ka_;
            if (s.lit) {
              T x = glm::dot(n, s.L);
              term += kd_ * clamp0(x);
              if (specular_) term += ks_ * phongSpecular(mirror(n, s.L, x), v, n_);
            }
            acc += w * term;
          }
          out.diff = acc;
          return out;
        }
        V diff(0), spec(0);
        for (size_t k = 0; k < lights_.size(); ++k) {
          const PreparedLight<T>& l = lights_[k];
          LightSample<T> s = sample(k);
          if (!s.lit) continue;
          V w = s.att * l.color;
          T x = glm::dot(n, s.L);
          diff += w * clamp0(x);
          if (specular_) spec += w * phongSpecular(mirror(n, s.L, x), v, n_);
        }
        out.diff = diff, out.spec = spec;
        return out;
      }
      case ModelId::YiqLuma: {
        T dsum = 0, ssum = 0;
        for (size_t k = 0; k < lights_.size(); ++k) {
          const PreparedLight<T>& l = lights_[k];
          LightSample<T> s = sample(k);
          if (!s.lit) continue;
          T w = s.att * l.color_luma;
          T x = glm::dot(n, s.L);
          dsum += w * saturate(x);
          // saturate(R.V)^n: R.V <= 1 for unit vectors, so the upper clamp
          // only removes rounding, which the |R - V| form has none of.
          if (specular_) ssum += w * phongSpecular(mirror(n, s.L, x), v, n_);
        }
        out.dsum = dsum, out.ssum = ssum;
        return out;
      }
      case ModelId::Lambert:
      case ModelId::WrapAround:
      case ModelId::Hemispherical:
      case ModelId::BiDirectional:
      case ModelId::Trilight: {
        V acc = ambient_;
        for (size_t k = 0; k < lights_.size(); ++k) {
          const PreparedLight<T>& l = lights_[k];
          LightSample<T> s = sample(k);
          if (!s.lit) continue;
          acc += s.att * l.color * forsyth(glm::dot(n, s.L));
        }
        out.diff = acc;
        return out;
      }
      // Lambert-like diffuse terms of N.L and N.V: Minnaert, Oren-Nayar.
      case ModelId::Minnaert:
      case ModelId::OrenNayar: {
        V diff(0);
        for (size_t k = 0; k < lights_.size(); ++k) {
          const PreparedLight<T>& l = lights_[k];
          LightSample<T> s = sample(k);
          if (!s.lit) continue;
          const T x = glm::dot(n, s.L), y = glm::dot(n, v);
          const T o = kind_ == ModelId::Minnaert ? minnaert(x, y, n_)
                      : on_cycles_             ? orenNayarCycles(x, y, glm::dot(s.L, v), on_a_, on_b_)
                                               : orenNayarQualitative(x, y, glm::dot(s.L, v), on_a_, on_b_);
          diff += s.att * l.color * o;
        }
        out.diff = diff;
        return out;
      }
      // A Lambert diffuse and a highlight: blinn_phong's clamp(N.H)^n or
      // cook_torrance's microfacet S (its ka is 1).
      case ModelId::BlinnPhong:
      case ModelId::CookTorrance: {
        V diff(0), spec(0);
        for (size_t k = 0; k < lights_.size(); ++k) {
          const PreparedLight<T>& l = lights_[k];
          LightSample<T> s = sample(k);
          if (!s.lit) continue;
          V w = s.att * l.color;
          diff += w * clamp0(glm::dot(n, s.L));
          if (specular_)
            spec += w * (kind_ == ModelId::BlinnPhong
                             ? phongSpecular(halfVector(s.L, v), n, n_)
                             : cookTorranceSpecular(n, s.L, v, ct_.distribution, ct_.geometry, ct_.fresnel,
                                                    T(ct_.roughness), T(ct_.f0)));
        }
        out.diff = diff, out.spec = spec;
        return out;
      }
    }
    return out;  // unreachable: the switch covers every ModelId
  }

  // The material's model (the formulas above) from its sums (lit) and c.
  V colourOf(const LightSums& s, V c) const {
    using namespace models;
    switch (kind_) {
      case ModelId::ClassicPhong:
        if (course_) return c * s.diff;
        return c * (ka_ * ambient_ + kd_ * s.diff) + ks_ * s.spec;
      case ModelId::YiqLuma: {
        T dl = saturate(ambient_luma_ + kd_ * s.dsum);
        return yiqLuma(c, dl, ks_ * s.ssum, offset_);
      }
      case ModelId::Lambert:
      case ModelId::WrapAround:
      case ModelId::Hemispherical:
      case ModelId::BiDirectional:
      case ModelId::Trilight: return c * s.diff;
      case ModelId::Minnaert:
      case ModelId::OrenNayar: return c * (ambient_ + kd_ * s.diff);
      case ModelId::BlinnPhong:
      case ModelId::CookTorrance: return c * (ka_ * ambient_ + kd_ * s.diff) + ks_ * s.spec;
    }
    return V(0);  // unreachable: the switch covers every ModelId
  }

  V mirror(V n, V L, T x) const {
    const V r = models::reflect(n, L, x);
    if (!unit_reflection_) return r;
    const T len = glm::length(r);
    return len > T(0) ? r / len : V(0);
  }

  V forsyth(T x) const {
    using namespace models;
    switch (kind_) {
      case ModelId::Lambert: return c0_ * lambert(x);
      case ModelId::WrapAround: return c0_ * wrapAround(x, factor_);
      case ModelId::Hemispherical: return hemispherical(x, c0_, c2_);
      case ModelId::BiDirectional: return biDirectional(x, c0_, c2_);
      case ModelId::Trilight: return trilight(x, c0_, c1_, c2_);
      case ModelId::ClassicPhong:
      case ModelId::YiqLuma:
      case ModelId::Minnaert:
      case ModelId::BlinnPhong:
      case ModelId::OrenNayar:
      case ModelId::CookTorrance: break;  // not of Forsyth's family: shade() does not call this
    }
    return V(0);
  }

  // One overload per model (a model without one does not compile).
  void setParams(const ClassicPhong& m) {
    kind_ = ModelId::ClassicPhong;
    course_ = m.variant == ClassicPhong::Variant::Course;
    ka_ = T(m.ka), kd_ = T(m.kd), ks_ = T(m.ks), n_ = T(m.shininess);
    specular_ = m.ks != 0.0;
  }
  void setParams(const YiqLuma& m) {
    kind_ = ModelId::YiqLuma;
    kd_ = T(m.kd), ks_ = T(m.ks), n_ = T(m.shininess), offset_ = T(m.luma_offset);
    specular_ = m.ks != 0.0;
  }
  void setParams(const Lambert& m) { kind_ = ModelId::Lambert, c0_ = V(m.c0); }
  void setParams(const WrapAround& m) { kind_ = ModelId::WrapAround, c0_ = V(m.c0), factor_ = T(m.factor); }
  void setParams(const Hemispherical& m) { kind_ = ModelId::Hemispherical, c0_ = V(m.c0), c2_ = V(m.c2); }
  void setParams(const BiDirectional& m) { kind_ = ModelId::BiDirectional, c0_ = V(m.c0), c2_ = V(m.c2); }
  void setParams(const Trilight& m) { kind_ = ModelId::Trilight, c0_ = V(m.c0), c1_ = V(m.c1), c2_ = V(m.c2); }

  // minnaert, blinn_phong, oren_nayar (n_ carries Minnaert's k).
  void setParams(const Minnaert& m) { kind_ = ModelId::Minnaert, kd_ = T(m.kd), n_ = T(m.k); }
  void setParams(const BlinnPhong& m) {
    kind_ = ModelId::BlinnPhong;
    ka_ = T(m.ka), kd_ = T(m.kd), ks_ = T(m.ks), n_ = T(m.shininess);
    specular_ = m.ks != 0.0;
  }
  void setParams(const OrenNayar& m) {
    kind_ = ModelId::OrenNayar, kd_ = T(m.kd);
    on_cycles_ = m.variant == OrenNayar::Variant::Cycles;
    const models::OrenNayarAB ab =
        on_cycles_ ? models::orenNayarCyclesAB(m.sigma) : models::orenNayarQualitativeAB(m.sigma);
    on_a_ = T(ab.a), on_b_ = T(ab.b);
  }
  void setParams(const CookTorrance& m) {
    kind_ = ModelId::CookTorrance, ct_ = m;
    ka_ = 1, kd_ = T(m.kd), ks_ = T(m.ks);
    specular_ = m.ks != 0.0;
  }

  ModelId kind_ = ModelId::ClassicPhong;
  glm::dvec3 origin_{0};
  std::optional<LumaSpace> luma_only_;
  std::vector<PreparedLight<T>> lights_;
  V ambient_{0};
  T ambient_luma_ = 0;
  bool course_ = false, specular_ = false, unit_reflection_ = false;
  T ka_ = 1, kd_ = 1, ks_ = 1, n_ = 55, offset_ = T(0.1), factor_ = 0;
  V c0_{1}, c1_{0}, c2_{0};
  bool on_cycles_ = false;  // oren_nayar: its variant and constants
  T on_a_ = 1, on_b_ = 0;
  CookTorrance ct_;  // its choices, roughness and f0
};

}  // namespace xval
