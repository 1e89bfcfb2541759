// The POV-Ray shading of a scene as values, before any SDL is written:
// the emission pigment tree (everything but the specular term) and the
// light sources and finish that give the specular term with POV-Ray's own
// `phong` (docs/povray-export.md). pov_exporter.cpp writes exactly this;
// tests/unit/pov_shading_test.cpp evaluates it with POV-Ray's documented
// semantics against the reference shader.
#pragma once

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

#include "povray/pigment_tree.h"
#include "scene/scene.h"

namespace xval::pov {

// light_source { location rgb colour [parallel point_at <0,0,0>]
//   [fade_distance fd fade_power p]
//   [spotlight point_at p radius r falloff r tightness 0] }
struct LightSource {
  glm::dvec3 location{0.0}, colour{0.0};
  bool parallel = false;     // L = normalize(location - <0,0,0>) everywhere
  double fade_distance = 0;  // > 0: att = 2 / (1 + (d / fade_distance)^fade_power)
  int fade_power = 2;        // 2 or 1
  bool spotlight = false;    // a hard cone: radius = falloff, tightness 0
  glm::dvec3 point_at{0.0};
  double cone_deg = 0;       // radius = falloff
};
std::string lightSourceSdl(const LightSource& l);
// The light sources whose sum is `light` with colour `colour` and its
// attenuation, exactly: none, constant (colour / c), 1/(c + l d) and
// 1/(c + q d^2) by fade_power 1 and 2, 1/(c + l d + q d^2) with real
// roots apart as two sources of fade_power 1 (the second of negative
// colour); nullopt for any other attenuation (no sum of light sources
// gives it). An ambient light has no light source: not for one.
std::optional<std::vector<LightSource>> lightSourcesOf(const Light& light, glm::dvec3 colour);

struct Specular {
  double ks = 0.0, shininess = 0.0;  // finish { phong ks phong_size shininess }
  // issue #33's blinn_phong: finish { specular ks roughness 1/shininess }
  // instead (POV-Ray: ks max(N.H, 0)^(1/roughness), H = normalize(L + V)).
  bool blinn = false;
  std::vector<LightSource> light_sources;
  // A texture_map over this pattern blends the material without (0) and
  // with (1) the phong term: the one general attenuation of the highlight.
  std::optional<Pattern> att_texture_map;
  // `double_illuminate` on the objects removes POV-Ray's N.L > 0 gate on
  // the highlight, which the paper's shader does not have.
  bool doubleIlluminate() const { return ks != 0.0; }
};

struct PovShading {
  Pigment emission;  // finish { ambient 0 diffuse 0 emission 1 }
  Specular specular;
  // When set, the material is a layered texture: the emission and phong
  // layer under a layer of filter 1 whose colour is the texture colour C
  // (filterLayerSdl), so the whole result, highlight included, is C (x)
  // (emission + phong). Emission and light colours are then those of C = 1.
  bool texture_filter_layer = false;
};

// Throws ExportError for what POV-Ray cannot compute exactly in one render.
// Not for Gouraud shading (its colours are the reference shader's).
PovShading povShading(const Scene& scene);
// The shading of an object of `material` in `scene` (the scene's lights,
// camera and shading mode; an object's own material, scene.h materialOf).
PovShading povShading(const Scene& scene, const Material& material);

}  // namespace xval::pov
