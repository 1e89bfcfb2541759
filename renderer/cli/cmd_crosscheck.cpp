// xval crosscheck SCENE.json --renderer povray -o DIR [--tolerances FILE]
//
// Renders the scene with the reference renderer and with an external
// renderer, compares them with the declared tolerance, and writes
// DIR/reference.exr, DIR/<renderer>.exr, DIR/diff.exr, DIR/metrics.json.
// Exit 0: within tolerance; 1: not; 2: an error (bad scene, renderer
// missing, failing or timing out: never a pass).
#include <chrono>
#include <cstdio>
#include <fstream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "image/compare.h"
#include "image/perceptual.h"
#include "blender/blender_render.h"
#include "povray/pov_render.h"
#include "blender/native_lambert.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "validate/tolerances.h"

namespace xval::cli {

void addCrosscheckCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string scene, renderer = "povray", dir, tolerances;
    double timeout = kDefaultToolTimeoutSeconds;
    BudgetOptions budget;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "crosscheck",
      "Render a scene with the reference renderer and an external one, and compare them with "
      "the tolerance declared for that case.\nExit 0 within tolerance, 1 outside, 2 on an error "
      "(a missing, failing or hanging renderer is an error, never a pass).");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("--renderer", args->renderer,
                  "External renderer: povray, blender (the model as shader nodes), or "
                  "blender-native (Blender's own Lambert vs the reference Lambert: see "
                  "docs/blender-export.md)")
      ->check(CLI::IsMember({"povray", "blender", "blender-native"}));
  cmd->add_option("-o,--output", args->dir, "Output folder")->required();
  cmd->add_option("--tolerances", args->tolerances, kToleranceFileHelp);
  cmd->add_option("--timeout", args->timeout, "Seconds before the external renderer is killed")
      ->check(Seconds);
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, &run]() {
    run = [args]() -> int {
      try {
        Scene scene = loadScene(args->scene, args->budget.get());
        std::filesystem::path dir(args->dir);
        std::filesystem::create_directories(dir);
        const FolderLock folder_lock(dir, FolderLock::Mode::Exclusive, "xval crosscheck");
        std::filesystem::remove(dir / "metrics.json");
        const ToleranceFile tol_file = findToleranceFile(args->tolerances, {args->scene});
        const ToleranceTable table = loadTolerances(tol_file.path);
        std::printf("tolerances: %s\n", tol_file.describe().c_str());
        std::string reason;
        Tolerance tol = table.lookup(scene, args->renderer, &reason);

        auto t0 = std::chrono::steady_clock::now();
        RenderOptions opt = defaultOptions(scene);
        opt.precision = Precision::Double;  // the exact reference path
        Image ref = renderScene(scene, opt);
        double ref_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        writeImage(ref, dir / "reference.exr");
        ExternalRenderInfo info;
        const std::filesystem::path work = dir / (args->renderer + ".work");
        makeFreshFolder(work);  // nothing from an earlier attempt, no planted link
        Image ext;
        if (args->renderer == "povray") {
          ext = renderWithPovray(scene, work, args->timeout, &info);
        } else if (args->renderer == "blender") {
          ext = renderWithBlender(scene, work, args->timeout, &info);
        } else {
          ext = renderWithBlender(scene, work, args->timeout, &info, BlenderMode::NativeLambert);
          scaleNativeLambert(scene, ext);
        }
        writeImage(ext, dir / (args->renderer + ".exr"));
        CompareMetrics m = compareImages(ref, ext, tol);
        writeImage(differenceImage(ref, ext), dir / "diff.exr");
        PerceptualMetrics pm = perceptualMetrics(ref, ext);
        nlohmann::json j = nlohmann::json::parse(toJson(m, tol, &pm));
        j["scene"] = scene.name;
        j["renderer"] = args->renderer;
        j["tolerance_reason"] = reason;
        j["tolerance_file"] = {{"path", tol_file.path.string()}, {"found_by", tol_file.found_by}};
        j["seconds"] = {{"reference", ref_s}, {args->renderer, info.seconds}};
        if (info.render_seconds >= 0) j["seconds"][args->renderer + "_render"] = info.render_seconds;
        writeFileAtomically(dir / "metrics.json", j.dump(2) + "\n");
        const bool pass = tol.passes(m);
        std::printf(
            "%s vs %s: %s  max %.2f  p99.9 %.2f  RMSE %.3f (x/65535)  within %.0f: %.4f%% (need "
            "%.2f%%)  masks: %lld off (%lld on silhouettes)  over tolerance: %lld (occlusion edge "
            "%lld, backfacing normal %lld, grazing %lld, unexplained %lld)  time: reference %.2f s, %s %.2f s\n",
            scene.name.c_str(), args->renderer.c_str(), pass ? "PASS" : "FAIL",
            m.max_abs * 65535, m.p999_abs * 65535, m.rmse * 65535, tol.max_abs * 65535,
            100 * m.fraction_within, 100 * tol.fraction, m.mask_disagree,
            m.mask_disagree_silhouette, m.over_tolerance, m.over_occlusion_edge, m.over_backfacing,
            m.over_grazing, m.over_unexplained, ref_s, args->renderer.c_str(), info.seconds);
        if (!reason.empty()) std::printf("  declared tolerance: %s\n", reason.c_str());
        return pass ? 0 : 1;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "xval crosscheck: error: %s\n", e.what());
        return 2;
      }
    };
  });
}

}  // namespace xval::cli
