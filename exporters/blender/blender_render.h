// Rendering a scene with Blender 3.4 (Cycles, or EEVEE: the same node
// tree through Blender's real-time rasteriser): export glTF, run
//   blender -b --factory-startup -P exporters/blender/render_gltf.py -- ...
// with a time-out, and read its float EXR back as an Image. At render.spp =
// n^2 Blender renders n W x n H pixels, one sample through each centre,
// and the n x n blocks are box-filtered (common/supersample.h): each
// sample's colour saturated as the reference renderer's, then averaged;
// alpha = the fraction of samples that hit; the unsaturated mean kept in
// raw.
#pragma once

#include <filesystem>

#include "image/image.h"
#include "common/export_common.h"
#include "scene/scene.h"

namespace xval {

enum class BlenderMode {
  Model,          // the scene's lighting model as shader nodes (emission)
  NativeLambert,  // Blender's own Diffuse BSDF, diffuse-direct pass
};

enum class BlenderEngine {
  Cycles,  // the path tracer, one sample per pixel centre
  Eevee,   // the rasteriser, headless on surfaceless EGL (Model mode only)
};

// The render_gltf.py script: $XVAL_BLENDER_SCRIPT, else the copy beside the
// xval executable's source tree (compiled in), which must exist.
std::filesystem::path blenderScript();

// Throws ExportError when the harness cannot render the scene exactly
// with that engine (checked before anything is exported; the glTF exporter
// may refuse more).
void checkBlenderScene(const Scene& scene, BlenderEngine engine = BlenderEngine::Cycles);

Image renderWithBlender(const Scene& scene, const std::filesystem::path& work_dir,
                        double timeout_seconds, ExternalRenderInfo* info = nullptr,
                        BlenderMode mode = BlenderMode::Model,
                        BlenderEngine engine = BlenderEngine::Cycles);

}  // namespace xval
