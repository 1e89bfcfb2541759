#include "blender/blender_render.h"


#include <atomic>
#include <charconv>
#include <optional>
#include <thread>
#include <chrono>
#include <exception>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include <nlohmann/json.hpp>

#include "blender/multilayer_exr.h"
#include "blender/native_bsdf.h"
#include "files/atomic_write.h"
#include "process/run_process.h"
#include "scene/json_reader.h"
#include "common/supersample.h"
#include "gltf/gltf_exporter.h"

namespace xval {

std::filesystem::path blenderScript() {
  if (const char* env = std::getenv("XVAL_BLENDER_SCRIPT")) return env;
  return XVAL_BLENDER_SCRIPT_DEFAULT;
}

namespace {

// A direct pass of a multilayer EXR ("DiffDir": channels "<layer>.DiffDir.R"
// ...), with alpha from the combined pass.
Image readPass(const std::filesystem::path& file, int width, int height, const std::string& pass) {
  const MultilayerChannels in =
      readMultilayerChannels(file, width, height, {pass + ".R", pass + ".G", pass + ".B", "Combined.A"});
  Image img(in.width, in.height, false);
  for (size_t i = 0; i < size_t(in.width) * size_t(in.height); ++i)
    for (size_t c = 0; c < 4; ++c) img.rgba[i * 4 + c] = in.at(i, c);
  return img;
}

// The shortest decimal that reads back as v (Python's float() reads it).
std::string exactDecimal(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

// Blender prints " Time: MM:SS.ss (Saving: ...)" after a render.
double renderTimeFromLog(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  double found = -1.0;
  while (std::getline(in, line)) {
    auto at = line.find(" Time: ");
    int mm;
    double ss;
    if (at != std::string::npos && std::sscanf(line.c_str() + at, " Time: %d:%lf", &mm, &ss) == 2)
      found = mm * 60.0 + ss;
  }
  return found;
}

}  // namespace

void checkBlenderScene(const Scene& scene, BlenderEngine engine) {
  // render.spp = n^2: Blender renders n W x n H pixels, one sample through
  // each centre (common/supersample.h); the grid's limits are the harness's.
  subpixelGrid(scene);
  // EEVEE's Image Texture, Linear, is trilinear on the GPU; Cycles has no
  // such lookup.
  if (engine == BlenderEngine::Cycles)
    refuseTrilinear(scene, "blender (Cycles)",
                    "Cycles filters an image texture on its one level (Linear is bilinear, no mip-maps on the "
                    "CPU) and a path-traced ray carries no pixel footprint to choose a level from");
}

namespace {

// One scene, exported and ready for Blender: what its image is read back
// against.
struct PreparedScene {
  SubpixelGrid grid;
  std::filesystem::path gltf, out, log;
};

// Checks the scene and the paths, exports the glTF into work_dir and names
// this attempt's image. Throws ExportError / ExternalToolError.
PreparedScene prepareScene(const std::string& renderer, const Scene& scene, const std::filesystem::path& work_dir,
                           BlenderEngine engine, const ExportThrough& through) {
  PreparedScene p;
  // Checked before anything is written.
  checkBlenderScene(scene, engine);
  p.grid = subpixelGrid(scene);
  const std::filesystem::path script = blenderScript();
  if (!std::filesystem::is_regular_file(script))
    throw ExternalToolError("Blender script " + script.string() +
                            " not found (set XVAL_BLENDER_SCRIPT)");
  // Blender reads '\\' in a path as a folder separator: such a path would
  // make it read or write elsewhere.
  const std::filesystem::path abs_work = std::filesystem::absolute(work_dir);
  for (const auto& path : {abs_work, std::filesystem::absolute(script)})
    if (path.string().find('\\') != std::string::npos)
      throw ExternalToolError(path.string() + ": contains '\\', which Blender reads as a folder separator; "
                              "choose a folder without it");
  exportThrough(through, work_dir, [&](const std::filesystem::path& dir) { exportGltf(scene, dir); });
  p.gltf = work_dir / kGltfFileName;
  // The image's name is this attempt's own: a Blender left from an earlier
  // attempt cannot supply it.
  p.out = abs_work / (renderer + "-" + attemptToken() + ".exr");
  p.log = work_dir / (renderer + ".log");
  return p;
}

// Blender's image of a prepared scene (`pass` empty: the combined image;
// Cycles' native mode: "DiffDir" or "GlossDir", one direct pass), read
// back, checked and box-filtered.
Image readBack(const std::string& tool, const PreparedScene& p, BlenderMode mode, const std::string& pass = "") {
  const SubpixelGrid& g = p.grid;
  Image fine;
  try {
    fine = pass.empty() ? readImage(p.out, g.width, g.height) : readPass(p.out, g.width, g.height, pass);
  } catch (const std::exception& e) {
    throw ExternalToolError(tool + " wrote an unusable image: " + e.what());
  }
  requireImageSize(tool, fine, g.width, g.height);
  requireFinite(tool, fine);
  // The EXR holds each sample unsaturated: keep it as raw for the box
  // filter's unsaturated mean.
  fine.raw.resize(size_t(fine.width) * fine.height * 3);
  for (size_t i = 0; i < size_t(fine.width) * fine.height; ++i)
    for (int c = 0; c < 3; ++c) fine.raw[i * 3 + c] = fine.rgba[i * 4 + c];
  // Model: each sample saturated, as the reference renderer's, then
  // averaged (boxFilter).
  Image img = boxFilter(fine, g.n);
  if (mode == BlenderMode::Native) {
    // A direct pass is weighted unsaturated (a physical
    // quantity): the unsaturated mean.
    for (size_t i = 0; i < size_t(img.width) * img.height; ++i)
      for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] = img.raw[i * 3 + c];
    img.raw.clear();
  }
  return img;
}

std::vector<std::string> blenderCommand() {
  return {"blender", "-b", "--factory-startup", "-noaudio", "-P",
          std::filesystem::absolute(blenderScript()).string(), "--"};
}

}  // namespace

Image renderWithBlender(const std::string& renderer, const Scene& scene, const std::filesystem::path& work_dir,
                        double timeout_seconds, ExternalRenderInfo* info, BlenderMode mode,
                        BlenderEngine engine, const ExportThrough& through) {
  // Native mode: the scene's built-in BSDF, checked before anything is
  // written (throws std::runtime_error with the reason).
  const std::optional<NativeBsdf> native =
      mode == BlenderMode::Native ? std::optional<NativeBsdf>(nativeBsdf(scene)) : std::nullopt;
  const PreparedScene p = prepareScene(renderer, scene, work_dir, engine, through);
  std::vector<std::string> argv = blenderCommand();
  for (const std::string& a :
       {std::string("--gltf"), std::filesystem::absolute(p.gltf).string(), std::string("--out"), p.out.string(),
        std::string("--mode"), std::string(mode == BlenderMode::Model ? "model" : "native"),
        std::string("--engine"), std::string(engine == BlenderEngine::Eevee ? "eevee" : "cycles")})
    argv.push_back(a);
  const NativeColours colours = native && engine == BlenderEngine::Eevee ? eeveeColours(*native) : NativeColours{};
  if (native)
    for (const std::string& a :
         {std::string("--diffuse-roughness"), exactDecimal(native->diffuse_roughness), std::string("--glossy"),
          std::string(glossyName(native->glossy)), std::string("--glossy-roughness"),
          exactDecimal(native->glossy_roughness), std::string("--diffuse-colour"), exactDecimal(colours.diffuse),
          std::string("--glossy-colour"), exactDecimal(colours.glossy)})
      argv.push_back(a);
  ProcessResult r = runProcess(argv, work_dir, p.log, timeout_seconds);
  if (info) *info = {r.seconds, p.log, renderTimeFromLog(p.log)};
  requireToolOutput(renderer, p.gltf, r, p.out);
  if (native && engine == BlenderEngine::Eevee) return scaleNativeCombined(colours.scale, readBack(renderer, p, mode));
  if (native)
    return combineNativePasses(*native, readBack(renderer, p, mode, "DiffDir"), readBack(renderer, p, mode, "GlossDir"));
  return readBack(renderer, p, mode);
}

namespace {

// What the worker's results file says: per position in its job list,
// whether it started and, when it finished, its outcome.
struct WorkerLine {
  bool started = false, done = false, ok = false;
  std::string error;
  double seconds = 0.0;
};

// Lines that are not the worker's records (a torn last line) are skipped:
// their job then counts as not done.
std::vector<WorkerLine> readWorkerResults(const std::filesystem::path& file, size_t jobs) {
  std::vector<WorkerLine> out(jobs);
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    nlohmann::json j;
    try {
      j = parseJsonText(line, file.string());  // the one strict reader (scene/json_reader.h)
    } catch (const SceneError&) {
      continue;
    }
    if (!j.is_object()) continue;
    auto index = [&](const char* key) -> long {
      const auto it = j.find(key);
      if (it == j.end() || !it->is_number_unsigned() || it->get<size_t>() >= jobs) return -1;
      return long(it->get<size_t>());
    };
    if (const long i = index("start"); i >= 0) out[size_t(i)].started = true;
    if (const long i = index("done"); i >= 0) {
      WorkerLine& w = out[size_t(i)];
      w.done = true;
      w.ok = j.value("ok", false);
      w.error = j.contains("error") && j["error"].is_string() ? j["error"].get<std::string>() : "";
      w.seconds = j.contains("seconds") && j["seconds"].is_number() ? j["seconds"].get<double>() : 0.0;
    }
  }
  return out;
}

std::string logTail(const std::filesystem::path& log) {
  return "\nlast lines of " + log.string() + ":\n" + tailOfFile(log);
}

}  // namespace

std::vector<BlenderBatchResult> renderBlenderBatch(const std::string& renderer,
                                                   const std::vector<BlenderBatchScene>& scenes,
                                                   double timeout_seconds, BlenderEngine engine,
                                                   const BlenderSceneDone& done) {
  std::vector<BlenderBatchResult> results(scenes.size());
  if (scenes.empty()) return results;
  const std::string& tool = renderer;
  std::vector<std::optional<PreparedScene>> prepared(scenes.size());
  std::vector<size_t> pending;
  for (size_t i = 0; i < scenes.size(); ++i) {
    try {
      prepared[i] = prepareScene(renderer, *scenes[i].scene, scenes[i].work_dir, engine, scenes[i].through);
      pending.push_back(i);
    } catch (const std::exception& e) {
      results[i].error = e.what();
      if (done) done(i, results[i]);
    }
  }
  const std::filesystem::path batch_dir = std::filesystem::absolute(scenes.front().work_dir);
  while (!pending.empty()) {
    // This attempt's own file names: nothing of an earlier process is read.
    const std::string token = attemptToken();
    const std::filesystem::path list = batch_dir / ("batch-" + token + ".json");
    const std::filesystem::path lines = batch_dir / ("batch-" + token + ".jsonl");
    const std::filesystem::path log = batch_dir / (tool + "-worker-" + token + ".log");
    nlohmann::json jobs = nlohmann::json::array();
    for (size_t i : pending) {
      const PreparedScene& p = *prepared[i];
      jobs.push_back({{"gltf", std::filesystem::absolute(p.gltf).string()},
                      {"out", p.out.string()},
                      {"log", std::filesystem::absolute(p.log).string()},
                      {"engine", engine == BlenderEngine::Eevee ? "eevee" : "cycles"}});
    }
    writeFileAtomically(list, nlohmann::json{{"jobs", jobs}}.dump(1) + "\n");
    std::vector<std::string> argv = blenderCommand();
    for (const std::string& a : {std::string("--batch"), list.string(), std::string("--results"), lines.string()})
      argv.push_back(a);
    // A scene the worker reported done: its result, read back, handed on.
    std::vector<char> finished(pending.size(), 0);
    auto finish = [&](size_t k, const WorkerLine& w) {
      const size_t i = pending[k];
      const PreparedScene& p = *prepared[i];
      BlenderBatchResult& out = results[i];
      out.info = {w.seconds, p.log, renderTimeFromLog(p.log)};
      try {
        if (!w.ok) throw ExternalToolError(tool + " (" + p.gltf.string() + "): " + w.error + logTail(p.log));
        if (!std::filesystem::exists(p.out))
          throw ExternalToolError(tool + " (" + p.gltf.string() + ") finished the scene but wrote no image " +
                                  p.out.string() + logTail(p.log));
        out.image = readBack(renderer, p, BlenderMode::Model);
      } catch (const std::exception& e) {
        out.error = e.what();
      }
      finished[k] = 1;
      if (done) done(i, out);
    };
    // While the process runs: the scenes it reports done (a "done" line is
    // written after the scene's image), each finished at once.
    std::atomic<bool> ended{false};
    std::exception_ptr watch_error;
    std::thread watcher;
    if (done)
      watcher = std::thread([&] {
        try {
          while (!ended.load()) {
            std::this_thread::sleep_for(std::chrono::duration<double>(kBatchPollSeconds));
            const std::vector<WorkerLine> now = readWorkerResults(lines, pending.size());
            for (size_t k = 0; k < pending.size() && !ended.load(); ++k)
              if (now[k].done && !finished[k]) finish(k, now[k]);
          }
        } catch (...) {
          watch_error = std::current_exception();
        }
      });
    ProcessResult r;
    try {
      r = runProcess(argv, batch_dir, log, timeout_seconds, lines);
    } catch (...) {
      ended = true;
      if (watcher.joinable()) watcher.join();
      throw;
    }
    ended = true;
    if (watcher.joinable()) watcher.join();
    if (watch_error) std::rethrow_exception(watch_error);
    const std::vector<WorkerLine> worker = readWorkerResults(lines, pending.size());
    std::vector<size_t> left;
    bool progressed = false;
    for (size_t k = 0; k < pending.size(); ++k) {
      const size_t i = pending[k];
      const PreparedScene& p = *prepared[i];
      BlenderBatchResult& out = results[i];
      const WorkerLine& w = worker[k];
      if (finished[k]) {
        progressed = true;
      } else if (w.done) {
        progressed = true;
        finish(k, w);
      } else if (w.started) {
        // The scene the process died on (the last one it started).
        progressed = true;
        out.info = {0.0, p.log, -1.0};
        out.error = tool + " (" + p.gltf.string() + "): the worker process " +
                    (r.ok() ? std::string("exited 0 without finishing the scene") : "ended: " + r.describe()) +
                    " while rendering this scene" + logTail(p.log) + logTail(log);
        if (done) done(i, out);
      } else {
        left.push_back(i);
      }
    }
    if (!left.empty() && (!progressed || r.ok())) {
      // A process that started no scene (or ended, status 0, without
      // them): another one would do the same.
      for (size_t i : left) {
        results[i].info = {0.0, log, -1.0};
        results[i].error = tool + " (" + prepared[i]->gltf.string() + "): the worker process " +
                           (r.ok() ? std::string("exited 0 without rendering this scene") : "ended: " + r.describe()) +
                           logTail(log);
        if (done) done(i, results[i]);
      }
      left.clear();
    }
    pending = left;
  }
  return results;
}

}  // namespace xval
