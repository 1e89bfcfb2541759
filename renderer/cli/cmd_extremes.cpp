// xval extremes -o DIR/ [--size N] [--only NAME,...] [--no-external]
//               [--renderers povray,blender,gl] [--jobs N] [--timeout S] [--threads N]
//
// The options of validate/extremes/run.h, which documents the run, what it
// writes, the defaults (--size 160, --only all cases, --jobs = hardware threads, --timeout 600 s, --threads =
// hardware threads) and the exit status: 0 no NaN/Inf in the reference
// renderer and no external error; 1 the reference renderer produced a
// NaN/Inf; 2 an error (bad option, a case that cannot be written or
// loaded, an external renderer that failed, timed out or is missing: an
// error, never a pass). --renderers: povray,blender,gl by default; eevee
// (a Blender process per case) only when named.
#include <cstdio>
#include <memory>
#include <sstream>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "common/export_common.h"  // kDefaultToolTimeoutSeconds
#include "validate/extremes/run.h"

namespace xval::cli {

void addExtremesCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string dir, only, renderers = "povray,blender,gl";
    int size = 160, jobs = 0, threads = 0;
    double timeout = kDefaultToolTimeoutSeconds;
    bool no_external = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "extremes",
      "Run the extremes matrix (docs/extremes.md): scenes at the edges of every model's domain "
      "(specular power 0..1e6, N.L near 0 and +-1, a light on the surface and 1e8 away, scale "
      "1e-6 and 1e6, black/white/saturated colours, a thin high-p,q knot, degenerate "
      "triangles, light at the eye, a spot cone's edge), each rendered by the reference "
      "renderer in float and double and by the external renderers of --renderers (default POV-Ray, "
      "Blender Cycles and gl). Writes DIR/scenes/*.json, "
      "DIR/extremes.json, DIR/extremes.md and heat maps.\n"
      "Exit 0: no NaN/Inf in the reference renderer and no external error; 1: the reference "
      "renderer produced a NaN/Inf; 2: an error (an external renderer failed: never a pass).");
  cmd->add_option("-o,--output", args->dir, "Output folder")->required();
  cmd->add_option("--size", args->size, "Pixels per side of every case (default 160)")
      ->check(CLI::Range(8, 4096));
  cmd->add_option("--only", args->only, "Comma-separated case names (default: all)");
  cmd->add_flag("--no-external", args->no_external,
                "Reference renderer only (float and double); no external renderer");
  cmd->add_option("--renderers", args->renderers,
                  "External renderers, comma-separated, of povray, blender, eevee and gl (default: povray,blender,gl; "
                  "eevee adds a Blender process per case)");
  cmd->add_option("--jobs", args->jobs, "External renders in parallel (default: the core count)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--timeout", args->timeout, "Seconds before an external renderer is killed (600)")
      ->check(Seconds);
  cmd->add_option("--threads", args->threads,
                  "Threads of each reference render (default: every hardware thread)")
      ->check(CLI::Range(1, 1024));
  cmd->callback([args, &run]() {
    run = [args]() -> int {
      try {
        extremes::ExtremesRun r;
        r.dir = args->dir;
        r.size = args->size;
        r.only = args->only;
        r.renderers.clear();
        if (!args->no_external) {
          std::stringstream ss(args->renderers);
          for (std::string item; std::getline(ss, item, ',');) r.renderers.push_back(item);
        }
        r.jobs = args->jobs, r.threads = args->threads, r.timeout = args->timeout;
        r.command = "xval extremes -o " + args->dir + (args->size != 160 ? " --size " + std::to_string(args->size) : "") +
                    (args->no_external ? " --no-external"
                     : args->renderers != "povray,blender,gl" ? " --renderers " + args->renderers
                                                              : "");
        return extremes::runExtremes(r);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "xval extremes: error: %s\n", e.what());
        return 2;
      }
    };
  });
}

}  // namespace xval::cli
