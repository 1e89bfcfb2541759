// xval bench SCENE [--frames N] [--runs R] [--spp N] [--threads T]
//                  [--renderers reference,povray,blender]
//
// Argument parsing only: what is timed and how is validate/bench/run.h.
#include <memory>
#include <sstream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/renderer_file_option.h"
#include "renderers/registry.h"
#include "validate/bench/run.h"

namespace xval::cli {

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
      "texture, BVH), which is printed apart, and diagnostics; validate-style frames (every diagnostic "
      "channel) are printed apart, with and without the precision probes, and so are the whole process of "
      "`xval render` (default outputs, --no-diagnostics, start-up alone) and its stages, and the "
      "performance targets (docs/performance.md) with the measured figures.");
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  const renderers::Registry& registry = renderers::registry();
  for (const std::string& id : registry.everySceneIds()) args->renderers += (args->renderers.empty() ? "" : ",") + id;
  cmd->add_option("--renderers", args->renderers,
                  "Comma-separated subset of " + renderers::joinNames(registry.ids()) + " (default: " +
                      args->renderers + ")");
  cmd->add_option("--frames", args->frames, "Reference frames per precision, and a real-time renderer's (gl) frames, after one warm-up (default 20)")
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
  auto renderer_files = addRendererFileOption(cmd);
  cmd->callback([args, renderer_files, &run]() {
    run = [args, renderer_files]() -> int {
      renderers::registerRendererFiles(*renderer_files);
      bench::BenchRequest r;
      r.scene_file = args->scene;
      std::stringstream ss(args->renderers);
      for (std::string id; std::getline(ss, id, ',');) r.renderers.push_back(id);
      if (args->spp) requirePerfectSquareSpp(args->spp, "--spp");
      r.frames = args->frames, r.runs = args->runs, r.spp = args->spp, r.threads = args->threads;
      r.precision = args->precision;
      r.timeout_seconds = args->timeout;
      r.json = args->json;
      r.budget = args->budget.get();
      return bench::runBench(r);
    };
  });
}

}  // namespace xval::cli
