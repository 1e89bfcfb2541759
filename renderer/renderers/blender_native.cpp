// blender-native: Blender's own BSDFs (Cycles' Diffuse BSDF, with its
// roughness, and its Glossy BSDF, GGX or Beckmann), not our shader-node
// rebuild of the model: a check of the models against the built-in ones
// and of geometry, camera and light conversion against Blender's own
// shading (blender/native_bsdf.h, docs/blender-export.md "Native tiers").
//
// Only for a restricted class of scenes (every_scene = false: `xval
// validate` renders with it only the scenes whose `renderers` name it;
// `xval crosscheck --renderer blender-native` runs it): an untextured white
// lambert, oren_nayar or cook_torrance (smith, no Fresnel) lit by one white
// point light with inverse-square attenuation, smooth shading. Blender
// renders the diffuse- and glossy-direct passes, which are weighted into
// the reference's units (4 pi^2 kd DiffDir + 4 pi^2 ks GlossDir, saturated
// at 1).
//
// Parameters (RenderRequest), as the blender renderer's:
//   work_dir         the glTF export, blender-native.log and the raw multilayer EXR
//   timeout_seconds  default kDefaultToolTimeoutSeconds (600)
// Needs what the blender renderer needs; same version line.
#include "blender/blender_render.h"
#include "blender/native_bsdf.h"
#include "renderers/blender_engine.h"

namespace xval::renderers {


Renderer nativeBsdfRenderer(BlenderEngine engine, const std::string& id, const std::string& display_name,
                            const std::string& summary) {
  Renderer r;
  r.id = id;
  r.display_name = display_name;
  r.summary = summary;
  r.every_scene = false;
  r.version_command = {"blender", "--version"};
  r.version_marker = "Blender";
  r.missing = blenderScriptMissing;
  r.cannot_express = [](const Scene& scene) -> std::string {
    try {
      nativeBsdf(scene);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return blenderRefusal(scene);
  };
  r.render = [engine, id = r.id](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    ExternalRenderInfo tool;
    Image image =
        renderWithBlender(id, scene, request.work_dir, request.timeout_seconds, &tool, BlenderMode::Native, engine);
    setInfo(info, tool);
    return image;
  };
  return r;
}

Renderer blenderNativeRenderer() {
  return nativeBsdfRenderer(BlenderEngine::Cycles, "blender-native", "Blender native BSDFs",
                            "Blender 3.4 Cycles' own Diffuse BSDF (with roughness) and Glossy BSDF (GGX, Beckmann); "
                            "white untextured, one point light scenes only");
}

}  // namespace xval::renderers
