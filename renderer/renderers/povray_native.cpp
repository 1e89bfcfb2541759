// povray-native: POV-Ray 3.7's OWN finish (diffuse, brilliance, phong,
// specular, ambient) against xval's models, not the emission pigments in
// which the povray renderer computes xval's math (povray/pov_native.h,
// docs/povray-export.md "Native tier").
//
// Only for a restricted class of scenes (every_scene = false: `xval
// validate` runs it on the scenes whose "renderers" field names it; `xval
// crosscheck --renderer povray-native` runs it): classic_phong paper,
// blinn_phong, grey lambert, and minnaert (as `brilliance`, the nearest
// built-in: a finding), lit by point, spot, directional and ambient lights
// whose attenuation fade gives exactly; smooth or flat shading; textures
// as a uv_mapping image_map. Anything else is refused with the reason.
//
// Parameters (RenderRequest), as the povray renderer's:
//   work_dir         the export (scene.pov, scene.ini, texture.png), the
//                    log (povray.log) and the raw image
//   timeout_seconds  default kDefaultToolTimeoutSeconds (600)
//   exported         the work folder holds the export already (exporter
//                    "pov-native"), else it is written there
// Needs `povray` on PATH; same version line as the povray renderer.
#include "povray/pov_exporter.h"
#include "povray/pov_render.h"
#include "renderers/export_cache.h"
#include "renderers/renderer.h"

namespace xval::renderers {

Renderer povrayRenderer();  // povray.cpp

Renderer povrayNativeRenderer() {
  // The povray renderer's tool, version line, process cost and arithmetic
  // (its precision model: the same SDL geometry and 16-bit output).
  Renderer r = povrayRenderer();
  r.id = "povray-native";
  r.display_name = "POV-Ray native finish";
  r.subject = "";
  r.summary = "POV-Ray 3.7's own finish (diffuse, phong, specular, brilliance) for xval's model; "
              "restricted scenes";
  r.every_scene = false;
  r.exporter = RendererExport{"pov-native", {},
                              [](const Scene& scene, const std::filesystem::path& dir) {
                                exportPov(scene, dir, "scene.png", PovTier::Native);
                              },
                              ""};
  r.cannot_express = [ex = *r.exporter](const Scene& scene) { return refusalOf(ex, scene); };
  r.render = [name = r.exporter->name, id = r.id](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    ExternalRenderInfo tool;
    Image image = renderWithPovray(id, scene, request.work_dir, request.timeout_seconds, &tool,
                                   request.exported ? exportedAlready() : cachedExport(name, request.export_key),
                                   PovTier::Native);
    setInfo(info, tool);
    return image;
  };
  return r;
}

}  // namespace xval::renderers
