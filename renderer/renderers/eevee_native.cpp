// eevee-native: Blender 3.4 EEVEE's own BSDFs (its Diffuse BSDF and its
// Glossy BSDF) against the reference's models, as blender-native does for
// Cycles (renderers/blender_native.cpp; blender/native_bsdf.h;
// docs/blender-export.md, "Native tiers"). The same scenes and nodes;
// EEVEE renders the combined image, the BSDFs' grey colours carrying the
// weights (blender/native_bsdf.h, eeveeColours).
//
// What EEVEE computes differs from Cycles' closures (findings, measured in
// docs/blender-export.md): its Diffuse BSDF ignores Roughness (plain
// Lambert), its Glossy BSDF is a linearly-transformed-cosine fit of GGX
// (Beckmann is drawn as GGX).
//
// Parameters (RenderRequest), as the eevee renderer's.
#include "renderers/blender_engine.h"

namespace xval::renderers {

Renderer eeveeNativeRenderer() {
  return nativeBsdfRenderer(BlenderEngine::Eevee, "eevee-native", "EEVEE native BSDFs",
                            "Blender 3.4 EEVEE's own Diffuse BSDF (roughness ignored) and Glossy BSDF (an LTC fit); "
                            "white untextured, one point light scenes only");
}

}  // namespace xval::renderers
