// xval tradeoff SCENE.json -o DIR/ [--frames N] [--max-seconds S] [--threads T]
//                [--quick] [--reference-spp N] [--reference-tessellation F]
//                [--width W] [--height H] [--metric M] [--images]
//
// The options of validate/tradeoff/run.h (which documents the run, its
// parameters and defaults, and what it writes). Exit 0, or 2 on an error
// (bad scene, gnuplot missing, ...).
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "image/metric_table.h"
#include "scene_file/scene_loader.h"  // kMaxImageSide
#include "validate/tradeoff/run.h"

namespace xval::cli {

void addTradeoffCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    TradeoffRun run;
    BudgetOptions budget;
  };
  auto args = std::make_shared<Args>();
  TradeoffRun& r = args->run;
  CLI::App* cmd = app.add_subcommand(
      "tradeoff",
      "Speed against accuracy of the reference renderer's knobs (samples per pixel, tessellation, "
      "float/double, flat/Gouraud/Phong, nearest/bilinear) on one scene: each configuration is "
      "prepared once, rendered once to warm up and timed over several frames (median, min..max; "
      "setup apart, diagnostics off), and its error measured against a converged reference "
      "(double, 64 spp, tessellation x4, Phong, bilinear; its own residual against one step "
      "finer each way is reported). Writes DIR/tradeoff.json, tradeoff.tsv, tradeoff.md and a "
      "Pareto plot pareto.png (gnuplot). The sweep: docs/tradeoff.md.");
  cmd->add_option("scene", r.scene_file, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", r.out, "Output folder (created)")->required();
  cmd->add_option("--frames", r.frames,
                  "Timed frames per configuration after one warm-up frame (default 5)")
      ->check(CLI::Range(1, 1000));
  cmd->add_option("--max-seconds", r.max_seconds,
                  "Stop timing a configuration once its timed frames add up to this many seconds "
                  "(default 3; at least one timed frame; a warm-up frame this long is itself the "
                  "one timed frame)")
      ->check(Seconds);
  cmd->add_option("--threads", r.threads, "Render threads (default: all hardware threads)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--quick", r.quick,
                "Leave out spp=64, tess=2 and corner:accurate; the reference defaults to 16 spp and "
                "tessellation x2 (not converged: for trying things out)");
  cmd->add_option("--reference-spp", r.reference_spp,
                  "Samples per pixel of the converged reference, a perfect square (default 64; "
                  "16 with --quick)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--reference-tessellation", r.reference_tessellation,
                  "Tessellation factor of the converged reference, times the scene's segments each "
                  "way (default 4; 2 with --quick)")
      ->check(FinitePositive);
  cmd->add_option("--width", r.width, "Override the camera's width in pixels (field of view kept)")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd->add_option("--height", r.height, "Override the camera's height in pixels")
      ->check(CLI::Range(1, kMaxImageSide));
  cmd->add_option("--metric", r.metric,
                  "Error on the Pareto plot and front (default rmse), an error of the metric table: " +
                      joinedIds(metricIds(true)))
      ->check(CLI::IsMember(metricIds(true)));
  cmd->add_flag("--images", r.images, "Also write every configuration's image as DIR/images/ID.exr");
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, &run]() {
    run = [args]() -> int {
      TradeoffRun r = args->run;
      r.budget = args->budget.get();
      if (r.reference_spp) requirePerfectSquareSpp(r.reference_spp, "--reference-spp");
      runTradeoff(r);
      return 0;
    };
  });
}

}  // namespace xval::cli
