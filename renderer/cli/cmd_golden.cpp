// xval golden update|check [SCENES or DIRS] [--renderer NAME] [--renderer-file FILE]: argument
// parsing; the work is validate/golden/golden_run.h.
//
// Exit (check): 0 every scene matches its golden image, 1 some does not
// (each printed with the command that accepts it), 2 an error (a renderer
// missing or failing, a malformed manifest). update: 0, or 2 on an error.
#include <cstdio>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/renderer_file_option.h"
#include "renderers/registry.h"
#include "validate/golden/golden_run.h"
#include "validate/tolerances.h"

namespace xval::cli {

void addGoldenCommand(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<validation::GoldenRequest>();
  auto budget = std::make_shared<BudgetOptions>();
  CLI::App* golden = app.add_subcommand(
      "golden",
      "Golden images: a renderer's images of a scene set stored beside it (SET/golden/RENDERER/<scene>.exr "
      "and manifest.json, for scenes in SET/scenes), for the `golden` renderers and regression checks "
      "(docs/golden-images.md).");
  golden->require_subcommand(1);
  const std::string renderer_help = "The renderer whose images are stored (default: the reference renderer; "
                                    "xval renderers lists them)";
  for (const char* action : {"update", "check"}) {
    const bool update = std::string(action) == "update";
    CLI::App* cmd = golden->add_subcommand(
        action, update ? "Render the scenes and store the images and the manifest entries (scene file hash, "
                         "settings hash, renderer and version, git commit, date), replacing earlier ones."
                       : "Render the scenes again and compare each with its golden image (the tolerance of the "
                         "id golden or golden-RENDERER). Exit 0 all match, 1 some do not (the command that "
                         "accepts each is printed), 2 on an error.");
    cmd->add_option("scenes", args->inputs, defaultScenesHelp());
    cmd->add_option("--renderer", args->renderer, renderer_help);
    if (!update) {
      cmd->add_option("--tolerances", args->tolerances, kToleranceFileHelp);
      cmd->add_option("--precision", args->precision,
                      "Reference renderer: double (the exact path the golden images are made with; default) or "
                      "float (the fast path, compared with the exact path's golden images)")
          ->check(CLI::IsMember({"double", "float"}));
    }
    cmd->add_option("--timeout", args->timeout_seconds, "Seconds before an external renderer is killed")
        ->check(Seconds);
    addBudgetOptions(cmd, *budget);
    // A renderer defined by a file stores and checks its own set,
    // golden/NAME beside the scenes (the renderer golden-NAME reads it).
    auto renderer_files = addRendererFileOption(cmd);
    cmd->callback([args, budget, update, renderer_files, &run]() {
      run = [args, budget, update, renderer_files]() -> int {
        if (args->renderer.empty()) args->renderer = renderers::registry().reference().id;
        if (args->inputs.empty())
          args->inputs = {toolkitSceneSet().string()};
        args->budget = budget->get();
        if (update) {
          renderers::registerRendererFiles(*renderer_files);
          return validation::goldenUpdate(*args);
        }
        try {
          renderers::registerRendererFiles(*renderer_files);
          return validation::goldenCheck(*args);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "xval golden check: error: %s\n", e.what());
          return 2;
        }
      };
    });
  }
}

}  // namespace xval::cli
