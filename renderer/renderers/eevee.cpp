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
// Batches as the blender renderer's: both are renderers/blender.cpp's
// blenderEngineRenderer (renderers/blender_engine.h).
#include "renderers/blender_engine.h"

namespace xval::renderers {

Renderer eeveeRenderer() {
  BlenderEngineFacts f;
  f.engine = BlenderEngine::Eevee;
  f.id = "eevee";
  f.display_name = "EEVEE";
  f.summary = "Blender 3.4 EEVEE: the blender renderer's node trees, rasterised on OpenGL (Mesa, headless)";
  // docs/precision-models.md, EEVEE.
  f.precision = {1.0, 1.0, std::ldexp(1.0, -10), 1e-5, 0.0,
                 "Mesa llvmpipe: float32 world positions, uv and normal varyings, exp2/log2 pow; RGBA32F"};
  return blenderEngineRenderer(f);
}

}  // namespace xval::renderers
