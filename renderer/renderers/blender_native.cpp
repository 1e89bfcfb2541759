// blender-native: Blender's own Lambert (its Diffuse BSDF), not our
// shader-node rebuild of the model: a check of geometry, camera and light
// conversion against Blender's own shading (blender/native_lambert.h,
// docs/blender-export.md).
//
// Only for a restricted class of scenes (every_scene = false: `xval
// validate` does not render every scene with it; `xval crosscheck
// --renderer blender-native` runs it): an untextured white Lambert lit by
// one white point light with inverse-square attenuation, smooth shading.
// Blender renders the diffuse-direct pass, which is scaled to the
// reference's units (DiffDir * 4 pi^2, saturated at 1).
//
// Parameters (RenderRequest), as the blender renderer's:
//   work_dir         the glTF export, blender-native.log and the raw multilayer EXR
//   timeout_seconds  default kDefaultToolTimeoutSeconds (600)
// Needs what the blender renderer needs; same version line.
#include "blender/blender_render.h"
#include "blender/native_lambert.h"
#include "renderers/blender_engine.h"

namespace xval::renderers {


Renderer blenderNativeRenderer() {
  Renderer r;
  r.id = "blender-native";
  r.display_name = "Blender native Lambert";
  r.summary = "Blender 3.4 Cycles' own Diffuse BSDF (white Lambert, one point light scenes only)";
  r.every_scene = false;
  r.version_command = {"blender", "--version"};
  r.version_marker = "Blender";
  r.missing = blenderScriptMissing;
  r.cannot_express = [](const Scene& scene) -> std::string {
    try {
      checkNativeLambertScene(scene);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return blenderRefusal(scene);
  };
  r.render = [id = r.id](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    ExternalRenderInfo tool;
    Image image =
        renderWithBlender(id, scene, request.work_dir, request.timeout_seconds, &tool, BlenderMode::NativeLambert);
    scaleNativeLambert(scene, image);
    setInfo(info, tool);
    return image;
  };
  return r;
}

}  // namespace xval::renderers
