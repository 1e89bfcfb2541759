// blender: Blender 3.4 (Cycles), run as an outside tool
// (blender/blender_render.h).
//
// The scene is exported as glTF (gltf/gltf_exporter.h) and rendered by
// `blender -b --factory-startup -P render_gltf.py`, which rebuilds the
// lighting model as shader nodes (an emission, so Cycles adds nothing of
// its own; docs/blender-export.md); its float EXR is read back, saturated
// per pixel as the reference does per sample, the unsaturated values kept
// as raw. A scene the harness cannot express is refused with its reason.
//
// Parameters (RenderRequest):
//   work_dir         the export (scene.gltf, scene.bin, texture.png), the
//                    log (blender.log) and the raw EXR
//   timeout_seconds  default kDefaultToolTimeoutSeconds (600)
//   exported         the work folder holds the export already (exporter
//                    "gltf": the check, then exportGltf's files)
// Needs `blender` on PATH and the harness script (blenderScript():
// $XVAL_BLENDER_SCRIPT, else the source tree's exporters/blender/
// render_gltf.py); version: the "Blender ..." line of `blender --version`.
// render_seconds: the log's render Time.
// Batches (render_batch): many scenes in one persistent Blender process
// (renderBlenderBatch), each from factory settings, each with its own log;
// the time-out applies per scene. `xval validate` batches by default
// (--batch).
#include "blender/blender_render.h"
#include "gltf/gltf_exporter.h"
#include "renderers/blender_engine.h"
#include "renderers/export_cache.h"

namespace xval::renderers {

// Why the harness cannot run on this machine ("" when it can): its script.
std::string blenderScriptMissing() {
  const std::filesystem::path script = blenderScript();
  if (std::filesystem::is_regular_file(script)) return "";
  return "Blender script " + script.string() + " not found (set XVAL_BLENDER_SCRIPT)";
}

namespace {

// The Blender harness's export with that engine: its check, then the glTF.
RendererExport blenderExport(BlenderEngine engine) {
  return {"gltf", [engine](const Scene& scene) { checkBlenderScene(scene, engine); },
          [](const Scene& scene, const std::filesystem::path& dir) { exportGltf(scene, dir); }, ""};
}

// The ExportThrough of a request: its work folder's export, or the cache's.
ExportThrough blenderThrough(const RenderRequest& request) {
  return request.exported ? exportedAlready() : cachedExport(blenderExport(BlenderEngine::Cycles).name, request.export_key);
}

// Many scenes in one Blender process (blender/blender_render.h
// renderBlenderBatch); the time-out is the first item's, per scene; each
// scene's outcome handed to item_done as soon as the worker finished it.
std::vector<BatchOutcome> blenderBatch(const std::string& id, const std::vector<BatchItem>& items, BlenderEngine engine,
                                       const BatchItemDone& item_done) {
  std::vector<BlenderBatchScene> scenes;
  for (const BatchItem& item : items) scenes.push_back({item.scene, item.request.work_dir, blenderThrough(item.request)});
  const double timeout = items.empty() ? kDefaultToolTimeoutSeconds : items.front().request.timeout_seconds;
  auto outcome = [](const BlenderBatchResult& r) {
    BatchOutcome o;
    o.image = r.image;
    o.error = r.error;
    setInfo(&o.info, r.info);
    return o;
  };
  BlenderSceneDone scene_done;
  if (item_done) scene_done = [&](size_t i, const BlenderBatchResult& r) { item_done(i, outcome(r)); };
  std::vector<BatchOutcome> out;
  for (const BlenderBatchResult& r : renderBlenderBatch(id, scenes, timeout, engine, scene_done)) out.push_back(outcome(r));
  return out;
}

}  // namespace

// The Cycles harness's refusal of a scene, "" when it can render it.
std::string blenderRefusal(const Scene& scene) { return refusalOf(blenderExport(BlenderEngine::Cycles), scene); }

// The Cycles and EEVEE renderers: one harness, one export, one batch
// runner; they differ in what BlenderEngineFacts holds.
Renderer blenderEngineRenderer(const BlenderEngineFacts& facts) {
  Renderer r;
  r.id = facts.id;
  r.display_name = facts.display_name;
  r.summary = facts.summary;
  r.version_command = {"blender", "--version"};
  r.version_marker = "Blender";
  r.cpu_share = facts.cpu_share;
  // Per scene of a batch: import, render, write (validate/validation/job_cost.h).
  r.job_cost = {1.5, 2.0, 10.0};
  r.precision = facts.precision;
  r.missing = blenderScriptMissing;
  r.exporter = blenderExport(facts.engine);
  r.cannot_express = [ex = *r.exporter](const Scene& scene) { return refusalOf(ex, scene); };
  r.render = [engine = facts.engine, id = r.id](const Scene& scene, const RenderRequest& request, RenderInfo* info) {
    ExternalRenderInfo tool;
    Image image = renderWithBlender(id, scene, request.work_dir, request.timeout_seconds, &tool, BlenderMode::Model,
                                    engine, blenderThrough(request));
    setInfo(info, tool);
    return image;
  };
  r.render_batch = [engine = facts.engine, id = r.id](const std::vector<BatchItem>& items,
                                                      const BatchItemDone& item_done) {
    return blenderBatch(id, items, engine, item_done);
  };
  return r;
}

Renderer blenderRenderer() {
  BlenderEngineFacts f;
  f.engine = BlenderEngine::Cycles;
  f.id = "blender";
  f.display_name = "Blender";
  f.summary = "Blender 3.4 Cycles: the scene exported as glTF, the model rebuilt as shader nodes";
  // A batch's worker process keeps 0.27-0.28 of a core busy on average
  // (process CPU over wall: 10.8 s of 39.2 s and 8.3 s of 30.4 s for the
  // two batches of the reference set at load average 6-8): most of its
  // time is Blender's start-up, the factory reset and the glTF import per
  // scene, on one thread. Half a core: the two batches of a 2-core run
  // leave a core to the POV-Ray and reference jobs beside them.
  f.cpu_share = 0.5;
  // docs/precision-models.md, Cycles.
  f.precision = {1.0, 1.0, std::ldexp(1.0, -10), 2e-6, 0.0,
                 "float32 Embree robust intersection, barycentric uv and normals, SVM math; float32 EXR"};
  return blenderEngineRenderer(f);
}

}  // namespace xval::renderers
