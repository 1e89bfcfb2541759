// eevee: Blender 3.4's real-time engine EEVEE, run as an outside tool
// (blender/blender_render.h, BlenderEngine::Eevee).
//
// The same glTF export and the same shader-node rebuild of the model as
// the blender renderer (Cycles), rendered by EEVEE's rasteriser headless on
// Mesa's surfaceless EGL (no X server). The harness sets what makes EEVEE's
// output exact (exporters/blender/render_gltf.py, docs/blender-export.md):
// one sample on each pixel centre, Standard view transform and a raw float
// EXR, a clip range fitted to the scene, bilinear lookups rebuilt from
// Closest ones, anisotropic filtering off. Supersampling and saturation as
// the blender renderer's. It refuses what the blender renderer refuses,
// except texture filter trilinear, which is EEVEE's own Linear lookup.
//
// Parameters (RenderRequest):
//   work_dir         the export, the log (eevee.log) and the raw EXR
//   timeout_seconds  default kDefaultToolTimeoutSeconds (600)
// Needs what the blender renderer needs (blender on PATH, the harness
// script); same version line. render_seconds: the log's render Time.
// Batches as the blender renderer's (renderers/blender.cpp).
#include "blender/blender_render.h"
#include "renderers/export_cache.h"
#include "renderers/renderer.h"

namespace xval::renderers {

std::string blenderScriptMissing();              // renderers/blender.cpp
RendererExport blenderExport(BlenderEngine engine);                 // renderers/blender.cpp
ExportThrough blenderThrough(const RenderRequest& request);        // renderers/blender.cpp
std::vector<BatchOutcome> blenderBatch(const std::vector<BatchItem>& items, BlenderEngine engine,
                                       const BatchItemDone& item_done);  // renderers/blender.cpp

Renderer eeveeRenderer() {
  Renderer r;
  r.id = "eevee";
  r.display_name = "EEVEE";
  r.summary = "Blender 3.4 EEVEE: the blender renderer's node trees, rasterised on OpenGL (Mesa, headless)";
  r.version_command = {"blender", "--version"};
  r.version_marker = "Blender";
  r.missing = blenderScriptMissing;
  // docs/precision-models.md, EEVEE.
  r.precision = {1.0, 1.0, std::ldexp(1.0, -10), 1e-5, 0.0,
                 "Mesa llvmpipe: float32 world positions, uv and normal varyings, exp2/log2 pow; RGBA32F"};
  r.exporter = blenderExport(BlenderEngine::Eevee);
  r.cannot_express = [ex = *r.exporter](const Scene& scene) { return refusalOf(ex, scene); };
  r.render = [](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    ExternalRenderInfo tool;
    Image image = renderWithBlender(scene, request.work_dir, request.timeout_seconds, &tool, BlenderMode::Model,
                                    BlenderEngine::Eevee, blenderThrough(request));
    setInfo(info, tool);
    return image;
  };
  r.render_batch = [](const std::vector<BatchItem>& items, const BatchItemDone& item_done) {
    return blenderBatch(items, BlenderEngine::Eevee, item_done);
  };
  return r;
}

}  // namespace xval::renderers
