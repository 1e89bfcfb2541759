// The native tiers: Blender's own BSDFs (Cycles' Diffuse BSDF, with or
// without roughness, and its Glossy BSDF) against the reference's models.
//
// A scene qualifies when its one material is untextured, base colour 1 on
// every object, lit by exactly one point light of colour (I, I, I) with the
// physical inverse square (attenuation {c ~ 0, 0, 1}), no ambient light,
// smooth (phong) shading; and its model is one a built-in BSDF computes:
//
//   model                       Blender's nodes (Cycles)                    our units
//   lambert c0 = 1              Diffuse, Roughness 0                        4 pi^2 DiffDir
//   oren_nayar cycles, kd       Diffuse, Roughness = sigma (sigma <= 1)     4 pi^2 kd DiffDir
//   oren_nayar qualitative, kd  Diffuse, Roughness = B/A                    4 pi kd A (pi + (3pi-4)/6 B/A) DiffDir
//                               (a finding: equal only where L.V > N.L N.V)
//   cook_torrance smith/none    Diffuse (Roughness 0) + Glossy GGX|Beckmann,
//                               Roughness = sqrt(alpha)                     4 pi^2 (kd DiffDir + ks GlossDir)
//
// Why 4 pi^2: Blender's RAW glTF import makes a point light of power P = I
// watts; with radius 0 Cycles delivers P / (4 pi) eval / d^2, eval being
// its BSDF x N.L (Lambert: N.L / pi). Our models write pi x BSDF x N.L per
// unit light (docs/models.md, "Normalisations"), so ours = 4 pi^2 x the
// pass (docs/blender-export.md, "Native tiers").
#pragma once

#include <string>

#include "image/image.h"
#include "scene/scene.h"

namespace xval {

// What the harness builds (render_gltf.py --mode native) and how its
// passes are weighted into the reference's units.
struct NativeBsdf {
  enum class Glossy { None, Ggx, Beckmann };
  double diffuse_roughness = 0.0;  // the Diffuse BSDF's Roughness socket
  Glossy glossy = Glossy::None;
  double glossy_roughness = 0.0;   // the Glossy BSDF's Roughness socket: sqrt(alpha)
  double diffuse_weight = 0.0;     // ours = diffuse_weight DiffDir + glossy_weight GlossDir
  double glossy_weight = 0.0;
};

// The Diffuse BSDF's Roughness that reproduces the qualitative Oren-Nayar
// where s > 0: Cycles' b/a = B/A (at most 0.9 for every sigma).
double cyclesRoughnessForQualitative(double sigma);
// The Glossy BSDF's Roughness for a microfacet width alpha: Cycles squares
// its Roughness socket (svm/closure.h: alpha = Roughness^2).
double cyclesGlossyRoughness(double alpha);

// The scene's native BSDF. Throws std::runtime_error, naming the scene and
// what it needs, when no built-in BSDF computes its model under its light.
NativeBsdf nativeBsdf(const Scene& scene);

// ours = saturate(diffuse_weight DiffDir + glossy_weight GlossDir) per
// channel; both images of one size; alpha from diffdir.
Image combineNativePasses(const NativeBsdf& bsdf, const Image& diffdir, const Image& glossdir);

// EEVEE (eevee-native) has no direct passes that exclude its BSDFs' colours
// as Cycles' do (its Specular Light pass is divided by the split-sum colour,
// not the node's): it renders the Combined image, with each BSDF's grey
// colour its weight / scale, scale the larger weight (colours <= 1).
struct NativeColours {
  double diffuse = 1.0, glossy = 1.0, scale = 1.0;  // ours = saturate(scale Combined)
};
NativeColours eeveeColours(const NativeBsdf& bsdf);
// ours = saturate(scale combined) per channel; alpha kept.
Image scaleNativeCombined(double scale, const Image& combined);

const char* glossyName(NativeBsdf::Glossy g);  // "none", "ggx", "beckmann": the harness's --glossy

}  // namespace xval
