// The POV-Ray native tier (renderer povray-native, docs/povray-export.md
// "Native tier"): xval's model written as POV-Ray 3.7's OWN finish, so that
// POV-Ray's built-in shading is compared with xval's model, instead of the
// emission pigments in which the povray renderer computes xval's math.
//
// POV-Ray 3.7.0.10's finish, per light source (trace.cpp; lights converted
// below, so Lc includes att):
//   every term only where N.L >= 1e-10 (N turned towards the viewer), unless
//   the object is double_illuminate (not written here);
//   diffuse   kd |N.L|^brilliance C Lc
//   phong     ks max(R.V, 0)^phong_size Lc         (white: no C, no N.L)
//   specular  ks max(N.H, 0)^(1/roughness) Lc      (H = normalize(L + V))
//   ambient   ka C A (global_settings ambient_light A; radiosity off)
// The conversions (NativeFinish):
//   classic_phong paper: ambient ka diffuse kd phong ks phong_size n
//   blinn_phong:         ambient ka diffuse kd specular ks roughness 1/n
//   lambert (grey c0):   ambient 1 diffuse c0
//   minnaert k:          ambient 1 diffuse kd brilliance k — the NEAREST
//     built-in, not an exact one: POV-Ray's kd (N.L)^k lacks Minnaert's
//     (N.V)^(k-1) (exact at k = 1). A scene naming this renderer with
//     minnaert k != 1 differs by design: a finding (the scene's
//     "findings" field says so), never a pass.
// The one built-in difference of the exact conversions: the gate on N.L
// (classic_phong's and blinn_phong's highlights are not gated in xval).
// Everything else without a built-in counterpart is refused (ExportError,
// nativeRefusal): the other models, classic_phong course, coloured c0,
// an exponent of 0, Gouraud shading, the luma-only mode, attenuation that
// no sum of light sources with fade gives.
#pragma once

#include <glm/glm.hpp>

#include <string>
#include <vector>

#include "povray/pov_shading.h"
#include "scene/scene.h"

namespace xval::pov {

// finish { ambient diffuse brilliance phong phong_size specular roughness }:
// the keywords POV-Ray is given (every one written, none left to POV-Ray's
// defaults: ambient 0.1, diffuse 0.6, phong_size 40, roughness 0.05).
struct NativeFinish {
  double ambient = 0.0, diffuse = 0.0, brilliance = 1.0;
  double phong = 0.0, phong_size = 0.0;  // phong 0: no phong term
  double specular = 0.0, roughness = 0.0;  // specular 0: no specular term
};

// The finish for a material's model; throws ExportError for a model POV-Ray
// has no built-in finish for.
NativeFinish nativeFinish(const Material& material);
std::string nativeFinishSdl(const NativeFinish& f);

// The scene's lights as POV-Ray light sources (point, spot, parallel;
// attenuation by fade_distance/fade_power or a pair of fade_power 1
// sources: lightSourcesOf) and the ambient lights' sum (ambient_light).
// Throws ExportError for an attenuation no light source gives.
struct NativeLights {
  std::vector<LightSource> sources;
  glm::dvec3 ambient_light{0.0};
};
NativeLights nativeLights(const Scene& scene);

// Throws ExportError for whatever in the scene the native tier cannot
// write (the models of every material, the lights, Gouraud shading, the
// luma-only mode); the export calls it first.
void checkNativeScene(const Scene& scene);

}  // namespace xval::pov
