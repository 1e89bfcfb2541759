// Rendering a scene (or a batch of scenes, renderBlenderBatch) with Blender 3.4 (Cycles, or EEVEE: the same node
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
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "common/export_common.h"
#include "scene/scene.h"

namespace xval {

enum class BlenderMode {
  Model,          // the scene's lighting model as shader nodes (emission)
  Native,  // Blender's own Diffuse / Glossy BSDFs (blender/native_bsdf.h), their direct passes
};

enum class BlenderEngine {
  Cycles,  // the path tracer, one sample per pixel centre
  Eevee,   // the rasteriser, headless on surfaceless EGL
};

// The render_gltf.py script: $XVAL_BLENDER_SCRIPT, else the copy beside the
// xval executable's source tree (compiled in), which must exist.
std::filesystem::path blenderScript();

// Throws ExportError when the harness cannot render the scene exactly
// with that engine (checked before anything is exported; the glTF exporter
// may refuse more).
void checkBlenderScene(const Scene& scene, BlenderEngine engine = BlenderEngine::Cycles);

// `renderer` (here and in renderBlenderBatch): the id of the registry entry
// rendering it (renderers/blender.cpp, eevee.cpp, blender_native.cpp): it
// labels the errors and names the log (<work_dir>/<renderer>.log) and the
// image.
Image renderWithBlender(const std::string& renderer, const Scene& scene, const std::filesystem::path& work_dir,
                        double timeout_seconds, ExternalRenderInfo* info = nullptr,
                        BlenderMode mode = BlenderMode::Model,
                        BlenderEngine engine = BlenderEngine::Cycles,
                        const ExportThrough& through = {});

// The persistent worker: many scenes (model mode) rendered by one Blender
// process (render_gltf.py --batch), each from factory settings, so each
// image is the one a process of its own renders. Each scene's export, log
// (<work_dir>/<renderer>.log) and image are in its own work_dir;
// the job list, the worker's results lines and its own log go in the first
// scene's work_dir. Per scene:
//   - a scene that fails (export refused, the harness's error, an unusable
//     image) is that scene's error, with the tail of its log;
//   - if the process dies (crash, signal, time-out: `timeout_seconds` per
//     scene, counted from the scene's start), the scene it died on is
//     reported with what happened, and the scenes not yet done are
//     rendered by a fresh process; a process that dies before starting
//     any scene fails every scene left.
// Returns one result per scene, in order. `done`, when not empty, is
// called once per scene with its final result as soon as it is final: for
// a scene the worker finished, while the process renders the next ones
// (a thread of this call polls the worker's result lines every
// kBatchPollSeconds and reads the scene's image back); for the others when
// the process has ended. One call at a time, never two at once; it must
// not throw (an exception from it is rethrown once the process has ended).
struct BlenderBatchScene {
  const Scene* scene = nullptr;
  std::filesystem::path work_dir;  // a fresh folder per scene
  ExportThrough through;           // how its glTF export is written (empty: exported)
};
struct BlenderBatchResult {
  std::optional<Image> image;   // set when the scene rendered
  std::string error;            // else why not
  ExternalRenderInfo info;      // seconds: the scene's part of the worker's time
};
using BlenderSceneDone = std::function<void(size_t scene, const BlenderBatchResult&)>;
inline constexpr double kBatchPollSeconds = 0.05;
std::vector<BlenderBatchResult> renderBlenderBatch(const std::string& renderer,
                                                   const std::vector<BlenderBatchScene>& scenes,
                                                   double timeout_seconds, BlenderEngine engine,
                                                   const BlenderSceneDone& done = {});

}  // namespace xval
