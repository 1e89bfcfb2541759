#include "validate/bench/run.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "files/atomic_write.h"
#include "files/scratch_folder.h"
#include "render/renderer.h"
#include "renderers/registry.h"
#include "scene/scene_loader.h"
#include "validate/common/frame_timing.h"

namespace xval::bench {

namespace {

std::string ms(const Spread& s) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%9.2f ms  (%.2f..%.2f, n=%zu)", s.median * 1e3, s.min * 1e3,
                s.max * 1e3, s.n);
  return buf;
}

}  // namespace

int runBench(const BenchRequest& request) {
  Scene scene = loadScene(request.scene_file, request.budget);
  const renderers::Registry& registry = renderers::registry();
  for (const std::string& r : request.renderers)
    if (!registry.find(r))
      throw std::runtime_error("--renderers: unknown renderer '" + r + "', expected " +
                               renderers::joinNames(registry.ids()));
  const std::vector<std::string>& which = request.renderers;
  auto wants = [&](const std::string& r) { return std::find(which.begin(), which.end(), r) != which.end(); };
  nlohmann::ordered_json out;
  out["scene"] = scene.name;
  out["width"] = scene.camera.width, out["height"] = scene.camera.height;
  out["hardware_threads"] = std::thread::hardware_concurrency();
  std::printf("xval bench %s (%dx%d), %u hardware threads\n", scene.name.c_str(),
              scene.camera.width, scene.camera.height, std::thread::hardware_concurrency());
  std::map<std::string, double> medians;
  const std::string reference_id = registry.reference().id;
  if (wants(reference_id)) {
    RenderOptions o = defaultOptions(scene);
    if (request.spp) {
      o.spp = request.spp;
      checkBudget(scene, o.spp, request.budget);
    }
    o.threads = request.threads;
    o.diagnostics = false;
    for (Precision p : {Precision::Float, Precision::Double}) {
      if (request.precision != "both" && request.precision != toString(p)) continue;
      o.precision = p;
      PreparedScene prepared(scene, p);
      Image img(scene.camera.width, scene.camera.height, false);
      RenderStats stats;
      prepared.render(o, img, &stats);  // warm-up
      const FrameTimes ft = timeFrames([&] { prepared.render(o, img); }, FrameBudget{request.frames},
                                       WarmUp::AlreadyDone);
      Spread s = spread(ft.wall_s), sc = spread(ft.cpu_s);
      const std::string key = reference_id + "_" + toString(p);
      medians[key] = s.median;
      std::printf("  %-18s frame %s   CPU time %s\n", key.c_str(), ms(s).c_str(), ms(sc).c_str());
      std::printf("  %-18s setup %.1f ms once, %zu triangles, %d spp, visibility: %s\n", "",
                  prepared.setupSeconds() * 1e3, prepared.triangleCount(), o.spp,
                  describeVisibility(stats).c_str());
      out[key] = {{"frame_median_s", s.median}, {"frame_min_s", s.min}, {"frame_max_s", s.max},
                  {"cpu_median_s", sc.median}, {"visibility", stats.visibility},
                  {"culled_triangles", stats.culled_triangles},
                  {"frames", s.n}, {"setup_s", prepared.setupSeconds()}, {"spp", o.spp}};
    }
  }
  for (const renderers::Renderer& renderer : registry.all()) {
    if (renderer.reference || !wants(renderer.id) || !renderer.prepare_frames) continue;
    // A real-time renderer: frames of one prepared scene, as the reference's.
    const std::string& r = renderer.id;
    const renderers::FrameLoop loop = renderer.prepare_frames(scene);
    const FrameTimes ft = timeFrames(loop.draw, FrameBudget{request.frames}, WarmUp::Render);
    Spread s = spread(ft.wall_s), sc = spread(ft.cpu_s);
    medians[r + "_frame"] = s.median;
    std::printf("  %-18s frame %s   CPU time %s\n", r.c_str(), ms(s).c_str(), ms(sc).c_str());
    std::printf("  %-18s %.1f frames per second (median frame), setup %.1f ms once, on %s\n", "",
                s.median > 0 ? 1.0 / s.median : 0.0, loop.setup_seconds * 1e3, loop.device.c_str());
    out[r] = {{"frame_median_s", s.median}, {"frame_min_s", s.min}, {"frame_max_s", s.max},
              {"cpu_median_s", sc.median}, {"frames_per_second", s.median > 0 ? 1.0 / s.median : 0.0},
              {"frames", s.n}, {"setup_s", loop.setup_seconds}, {"device", loop.device}};
  }
  for (const renderers::Renderer& renderer : registry.all()) {
    if (renderer.reference || !wants(renderer.id) || renderer.prepare_frames) continue;
    const std::string& r = renderer.id;
    std::vector<double> whole, own;
    // A private folder made for this run (files/scratch_folder.h), never a
    // name known in advance: the renderer's output, the scene and its
    // scratch folder go there.
    const ScratchFolder scratch("bench-" + r);
    const std::filesystem::path work = scratch.dir() / "work";
    for (int k = 0; k < request.runs; ++k) {
      renderers::RenderInfo info;
      renderer.render(scene, {work, request.timeout_seconds, {}}, &info);
      whole.push_back(info.seconds);
      if (info.render_seconds >= 0) own.push_back(info.render_seconds);
    }
    Spread sw = spread(whole), so = spread(own);
    medians[r + "_render"] = so.median;
    medians[r + "_process"] = sw.median;
    std::printf("  %-18s render %s   whole process %s\n", r.c_str(), ms(so).c_str(), ms(sw).c_str());
    out[r] = {{"render_median_s", so.median}, {"render_min_s", so.min}, {"render_max_s", so.max},
              {"process_median_s", sw.median}, {"process_min_s", sw.min},
              {"process_max_s", sw.max}, {"runs", sw.n}};
  }
  // Ratios of medians, against the fast path.
  const std::string base_key = reference_id + "_float";
  if (medians.count(base_key)) {
    const double base = medians[base_key];
    std::printf("  ratios to the reference float frame (medians):\n");
    for (const auto& [k, v] : medians) {
      if (k == base_key || v <= 0) continue;
      std::printf("    %-18s %8.1fx\n", k.c_str(), v / base);
      out["ratios_to_reference_float"][k] = v / base;
    }
  }
  if (!request.json.empty()) writeFileAtomically(request.json, out.dump(2) + "\n");
  return 0;
}

}  // namespace xval::bench
