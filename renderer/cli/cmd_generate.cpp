// xval generate SPEC.json -o DIR/ [--render]
#include <cstdio>
#include <fstream>
#include <memory>

#include "cli/commands.h"
#include "files/atomic_write.h"
#include "render/renderer.h"
#include "scene_file/scene_generator.h"
#include "scene_file/scene_loader.h"

namespace xval::cli {

void addGenerateCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string spec, dir;
    bool render = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "generate",
      "Write the scene files of a matrix spec (every combination of one value per axis; "
      "the spec format: docs/scene-format.md, \"Generated scene sets\"), each validated, optionally "
      "with its reference-renderer image.");
  cmd->add_option("spec", args->spec, "Generator spec (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->dir, "Output folder")->required();
  cmd->add_flag("--render", args->render, "Also render each scene with the reference renderer (DIR/NAME.exr, with the scene's render.spp "
                "and render.precision)");
  cmd->callback([args, &run]() {
    run = [args]() {
      std::vector<GeneratedScene> scenes = generateScenes(args->spec);
      std::filesystem::path dir(args->dir);
      std::filesystem::create_directories(dir);
      for (size_t i = 0; i < scenes.size(); ++i) {
        const auto& g = scenes[i];
        const std::filesystem::path file = dir / (g.name + ".json");
        writeFileAtomically(file, sceneForFolder(g, args->spec, dir).dump(2) + "\n");
        std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, scenes.size(), file.c_str());
        // Loaded back from where it now lives: its paths must resolve there.
        Scene s = loadScene(file);
        if (args->render) {
          writeImage(renderScene(s, defaultOptions(s)), dir / (g.name + ".exr"));
        }
      }
      std::fprintf(stderr, "xval generate: %zu scenes in %s\n", scenes.size(), args->dir.c_str());
      return 0;
    };
  });
}

}  // namespace xval::cli
