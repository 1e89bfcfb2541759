// Scenes covering every lighting model, light type and shading mode, with
// light and eye positions drawn from a fixed seed: the cases on which the
// exporters' shading (the Blender harness's node graph, the POV-Ray
// pigment trees) is evaluated numerically against Shader<double>. Also
// sample points, normals and surface colours for them.
#pragma once

#include <glm/glm.hpp>

#include <random>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace xval::test {

struct ShadingCase {
  std::string name;
  Scene scene;
};

class CaseRng {
 public:
  explicit CaseRng(unsigned seed) : rng_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  glm::dvec3 inBox(double r) { return {uniform(-r, r), uniform(-r, r), uniform(-r, r)}; }
  glm::dvec3 colour(double lo = 0.0, double hi = 1.0) {
    return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)};
  }
  // Uniform on the unit sphere.
  glm::dvec3 unit() {
    for (;;) {
      glm::dvec3 v = inBox(1.0);
      double l = glm::length(v);
      if (l > 0.1 && l <= 1.0) return v / l;
    }
  }
  unsigned index(unsigned n) { return unsigned(rng_() % n); }

 private:
  std::mt19937_64 rng_;
};

inline Attenuation someAttenuation(CaseRng& r, bool linear) {
  return {r.uniform(0.5, 2.0), linear ? r.uniform(0.05, 0.5) : 0.0, r.uniform(0.02, 0.3)};
}

// The light sets: each light type alone (with and without attenuation,
// linear term or not), and several together with ambient lights.
inline std::vector<std::pair<std::string, std::vector<Light>>> lightSets(CaseRng& r) {
  auto spot = [&r](Attenuation a) {
    SpotLight s;
    s.position = glm::dvec3(r.uniform(-1, 1), r.uniform(-1, 1), r.uniform(2.5, 4));
    s.direction = -s.position + r.inBox(0.4);
    s.direction *= r.uniform(0.5, 3.0);  // any length
    s.cutoff_deg = r.uniform(10, 40);
    s.color = r.colour(0.3, 1.0);
    s.attenuation = a;
    return s;
  };
  auto point = [&r](Attenuation a) {
    PointLight p;
    p.position = r.inBox(3.0) + glm::dvec3(0, 0, 2);
    p.color = r.colour(0.3, 1.0);
    p.attenuation = a;
    return p;
  };
  auto directional = [&r] {
    DirectionalLight d;
    d.direction = r.unit() * r.uniform(0.5, 2.0);
    d.color = r.colour(0.3, 1.0);
    return d;
  };
  std::vector<std::pair<std::string, std::vector<Light>>> sets;
  sets.push_back({"point", {point({})}});
  sets.push_back({"point_att_q", {point(someAttenuation(r, false))}});
  sets.push_back({"point_att_lq", {point(someAttenuation(r, true))}});
  sets.push_back({"spot", {spot({})}});
  sets.push_back({"spot_att_lq", {spot(someAttenuation(r, true))}});
  sets.push_back({"directional", {directional()}});
  sets.push_back({"several",
                  {AmbientLight{r.colour(0.0, 0.15)}, point(someAttenuation(r, false)), spot({}),
                   directional(), AmbientLight{r.colour(0.0, 0.1)}}});
  return sets;
}

inline std::vector<std::pair<std::string, LightingModel>> lightingModels(CaseRng& r) {
  std::vector<std::pair<std::string, LightingModel>> m;
  ClassicPhong paper{ClassicPhong::Variant::Paper, r.uniform(0.05, 0.3), r.uniform(0.5, 1.0),
                     r.uniform(0.2, 1.0), r.uniform(5, 80)};
  ClassicPhong course = paper;
  course.variant = ClassicPhong::Variant::Course;
  ClassicPhong diffuse_only = paper;
  diffuse_only.ks = 0.0;
  m.push_back({"phong_paper", paper});
  m.push_back({"phong_course", course});
  m.push_back({"phong_ks0", diffuse_only});
  m.push_back({"yiq", YiqLuma{r.uniform(0.2, 0.4), r.uniform(0.2, 1.0), r.uniform(5, 80), 0.1}});
  m.push_back({"yiq_bright", YiqLuma{r.uniform(0.9, 1.2), r.uniform(0.2, 1.0), r.uniform(5, 80), 0.1}});
  m.push_back({"lambert", Lambert{r.colour(0.3, 1.0)}});
  m.push_back({"wrap0", WrapAround{r.colour(0.3, 1.0), 0.0}});
  m.push_back({"wrap", WrapAround{r.colour(0.3, 1.0), r.uniform(0.1, 0.9)}});
  m.push_back({"wrap1", WrapAround{r.colour(0.3, 1.0), 1.0}});
  m.push_back({"hemispherical", Hemispherical{r.colour(0.3, 1.0), r.colour(0.0, 0.5)}});
  m.push_back({"bidirectional", BiDirectional{r.colour(0.3, 1.0), r.colour(0.0, 0.5)}});
  m.push_back({"trilight", Trilight{r.colour(0.3, 1.0), r.colour(0.0, 0.4), r.colour(0.0, 0.5)}});
  // issue #33's models, from a generator of their own (the cases above keep their values).
  CaseRng r33(33);
  m.push_back({"minnaert1", Minnaert{r33.uniform(0.5, 1.0), 1.0}});
  m.push_back({"minnaert", Minnaert{r33.uniform(0.5, 1.0), r33.uniform(1.2, 2.5)}});
  m.push_back({"blinn_phong", BlinnPhong{r33.uniform(0.05, 0.3), r33.uniform(0.5, 1.0), r33.uniform(0.2, 1.0),
                                         r33.uniform(5, 80)}});
  m.push_back({"oren_nayar_q", OrenNayar{OrenNayar::Variant::Qualitative, r33.uniform(0.5, 1.0), r33.uniform(0.2, 1.0)}});
  m.push_back({"oren_nayar_c", OrenNayar{OrenNayar::Variant::Cycles, r33.uniform(0.5, 1.0), r33.uniform(0.2, 1.0)}});
  {  // cook_torrance: fixed numbers (no draws, so the cases above keep their random numbers)
    using D = models::MicrofacetD;
    using G = models::MicrofacetG;
    using F = models::MicrofacetF;
    m.push_back({"ct_ggx_smith", CookTorrance{D::Ggx, G::Smith, F::None, 0.04, 0.3, 0.7, 0.6}});
    m.push_back({"ct_beckmann_vgroove", CookTorrance{D::Beckmann, G::VGroove, F::Schlick, 0.5, 0.35, 0.5, 0.8}});
    m.push_back({"ct_beckmann_smith", CookTorrance{D::Beckmann, G::Smith, F::Schlick, 0.9, 0.2, 0.6, 0.5}});
    m.push_back({"ct_ks0", CookTorrance{D::Ggx, G::Smith, F::None, 0.04, 0.25, 0.8, 0.0}});
  }
  return m;
}

// A small sphere lit by `model`, its eye position and base colour drawn
// from r; no lights yet.
inline Scene sphereScene(CaseRng& r, const std::string& name, const LightingModel& model) {
  Scene s;
  s.name = name;
  s.camera.position = r.unit() * r.uniform(2.5, 5.0);
  s.camera.width = s.camera.height = 16;
  UvSphere sphere;
  sphere.segments_longitude = 8, sphere.segments_latitude = 4;
  s.objects.push_back(sphere);
  s.material.model = model;
  s.material.base_color = r.colour(0.2, 1.0);
  return s;
}

// Case k of a list textured when k % every == 1: the brick, nearest and
// bilinear in turn.
inline void brickEvery(Scene& s, int k, int every) {
  if (k % every != 1) return;
  TextureSpec t;
  t.filter = ((k + 1) / every) % 2 ? TextureFilter::Nearest : TextureFilter::Bilinear;
  s.material.texture = t;
}

// Every model x light set x shading mode, a sixth of them textured (the
// brick, nearest and bilinear in turn), each with its own eye position; a small sphere as the object.
inline std::vector<ShadingCase> shadingCases(unsigned seed = 13) {
  CaseRng r(seed);
  std::vector<ShadingCase> out;
  const auto ms = lightingModels(r);
  int k = 0;
  for (const auto& [mname, model] : ms)
    for (const auto& [lname, lights] : lightSets(r))
      for (ShadingMode mode : {ShadingMode::Phong, ShadingMode::Flat, ShadingMode::Gouraud}) {
        Scene s = sphereScene(r, mname + "_" + lname + "_" + toString(mode), model);
        // Every sixth case textured (C then comes from the texture node;
        // exporting the texture is the slow part of the Blender check).
        brickEvery(s, k++, 6);
        s.lights = lights;
        s.shading = mode;
        out.push_back({s.name, s});
      }
  return out;
}

// The luma-only mode (colour/luma_only.h) on every model and each luma
// space: the light set with several coloured lights and ambients (where the
// grey lights differ most from the coloured ones), each shading mode, every
// third case textured. A case's name ends in its space.
inline std::vector<ShadingCase> lumaOnlyCases(unsigned seed = 33) {
  CaseRng r(seed);
  std::vector<ShadingCase> out;
  const auto ms = lightingModels(r);
  int k = 0;
  for (const auto& [mname, model] : ms)
    for (LumaSpace space : {LumaSpace::Yiq, LumaSpace::CieLstar})
      for (ShadingMode mode : {ShadingMode::Phong, ShadingMode::Flat, ShadingMode::Gouraud}) {
        Scene s = sphereScene(r, mname + "_several_" + toString(mode) + "_luma_only_" + toString(space), model);
        s.material.luma_only = space;
        brickEvery(s, k++, 3);
        s.lights = lightSets(r).back().second;  // "several"
        s.shading = mode;
        out.push_back({s.name, s});
      }
  return out;
}

}  // namespace xval::test
