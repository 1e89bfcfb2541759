// xval lint SCENE.json...: the scenes' warnings (lint/scene_lint.h), with
// nothing rendered. Warnings are advice: the exit status is 0 whatever
// they say (2 for a scene that does not load).
#include <cstdio>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "lint/scene_lint.h"
#include "scene_file/scene_loader.h"

namespace xval::cli {

void addLintCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::vector<std::string> scenes;
    BudgetOptions budget;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "lint",
      "Print the warnings of scenes that every renderer draws alike but that cannot be what was meant (a "
      "light or the camera inside a closed mesh, a Gouraud spot cone between the vertices, a black light: "
      "docs/scene-format.md, Warnings). validate, render and crosscheck print them too. Never fails on a "
      "warning.");
  cmd->add_option("scenes", args->scenes, "Scene files (JSON)")->required()->check(CLI::ExistingFile);
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, &run]() {
    run = [args]() {
      size_t warnings = 0;
      for (const std::string& file : args->scenes)
        warnings += printSceneWarnings("xval lint", loadScene(file, args->budget.get())).size();
      std::fprintf(stderr, "xval lint: %zu warning(s) in %zu scene(s)\n", warnings, args->scenes.size());
      return 0;
    };
  });
}

}  // namespace xval::cli
