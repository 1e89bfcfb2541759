// xval bench SCENE [--frames N] [--runs R] [--spp N] [--threads T]
//                  [--renderers reference,povray,blender]
//
// Whole-frame timings of one scene, in one run, side by side, for the
// renderers asked for (default: the registry's every-scene renderers,
// renderers/registry.h), in registry order:
//   reference float:  the fast path (Embree 16-ray packets, float shading);
//   reference double: the exact reference path;
//   the others:       the external renderer's own render time as it reports
//                     it, and its whole process (export, start-up, parse,
//                     render, read back).
// For the reference renderer the scene is prepared once (tessellation,
// texture, BVH: "setup", reported apart) and then --frames frames are
// rendered into one image after one warm-up frame: a frame is rays +
// shading + writing the pixels, without diagnostics (what an interactive
// renderer redoes every frame; the paper's Table 2 counts the same).
// Frame figures are wall-clock and the process's CPU time (all threads);
// on a busy machine only the CPU time means much.
// Every figure is the median over the repetitions with its spread
// (min..max); ratios are of medians. Timings are wall-clock on a machine
// that may be shared: run it on an idle machine.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "common/export_common.h"
#include "render/renderer.h"
#include "renderers/registry.h"
#include "scene/scene_loader.h"
#include "validate/common/frame_timing.h"

namespace xval::cli {

namespace {


std::string ms(const Spread& s) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "%9.2f ms  (%.2f..%.2f, n=%zu)", s.median * 1e3, s.min * 1e3,
                s.max * 1e3, s.n);
  return buf;
}

}  // namespace

void addBenchCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string scene, renderers, json, precision = "both";
    int frames = 20, runs = 3, spp = 0, threads = 0;
    double timeout = kDefaultToolTimeoutSeconds;
    BudgetOptions budget;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "bench",
      "Frame times of one scene with the reference renderer (float fast path and double "
      "reference path) and, in the same run, POV-Ray and Blender; prints medians, spread "
      "(min..max) and ratios. Reference frames exclude the one-time setup (tessellation, "
      "texture, BVH), which is printed apart, and diagnostics.");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  const renderers::Registry& registry = renderers::registry();
  for (const std::string& id : registry.everySceneIds()) args->renderers += (args->renderers.empty() ? "" : ",") + id;
  cmd->add_option("--renderers", args->renderers,
                  "Comma-separated subset of " + renderers::joinNames(registry.ids()) + " (default: " +
                      args->renderers + ")");
  cmd->add_option("--frames", args->frames, "Reference frames per precision after one warm-up (default 20)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--runs", args->runs, "Runs of each external renderer (default 3)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--spp", args->spp, "Samples per pixel for the reference renderer (default: the scene's)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--threads", args->threads, "Reference renderer threads (default: all hardware threads)")
      ->check(CLI::Range(1, 1024));
  cmd->add_option("--timeout", args->timeout, "Seconds before an external renderer is killed (default 600)")
      ->check(Seconds);
  cmd->add_option("--precision", args->precision,
                  "Reference paths to time: float (the fast path), double (the reference path) or "
                  "both (default)")
      ->check(CLI::IsMember({"float", "double", "both"}));
  cmd->add_option("--json", args->json, "Also write the figures to this JSON file");
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, &run]() {
    run = [args]() -> int {
      Scene scene = loadScene(args->scene, args->budget.get());
      const renderers::Registry& registry = renderers::registry();
      std::vector<std::string> which;
      {
        std::stringstream ss(args->renderers);
        std::string r;
        while (std::getline(ss, r, ','))
          if (registry.find(r))
            which.push_back(r);
          else
            throw std::runtime_error("--renderers: unknown renderer '" + r + "', expected " +
                                     renderers::joinNames(registry.ids()));
      }
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
        if (args->spp) {
          requirePerfectSquareSpp(args->spp, "--spp");
          o.spp = args->spp;
          checkBudget(scene, o.spp, args->budget.get());
        }
        o.threads = args->threads;
        o.diagnostics = false;
        for (Precision p : {Precision::Float, Precision::Double}) {
          if (args->precision != "both" && args->precision != toString(p)) continue;
          o.precision = p;
          PreparedScene prepared(scene, p);
          Image img(scene.camera.width, scene.camera.height, false);
          RenderStats stats;
          prepared.render(o, img, &stats);  // warm-up
          const FrameTimes ft = timeFrames([&] { prepared.render(o, img); }, FrameBudget{args->frames},
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
        if (renderer.reference || !wants(renderer.id)) continue;
        const std::string& r = renderer.id;
        std::vector<double> whole, own;
        const std::filesystem::path work =
            std::filesystem::temp_directory_path() / ("xval-bench-" + std::to_string(getpid()) + "-" + r);
        for (int k = 0; k < args->runs; ++k) {
          renderers::RenderInfo info;
          renderer.render(scene, {work, args->timeout, {}}, &info);
          whole.push_back(info.seconds);
          if (info.render_seconds >= 0) own.push_back(info.render_seconds);
        }
        std::filesystem::remove_all(work);
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
      if (!args->json.empty()) writeJsonFile(args->json, out);
      return 0;
    };
  });
}

}  // namespace xval::cli
