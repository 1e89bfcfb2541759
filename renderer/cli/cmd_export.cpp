// xval export pov|pov-native|gltf SCENE.json -o DIR/
#include <cstdio>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "gltf/gltf_exporter.h"
#include "povray/pov_exporter.h"
#include "scene_file/scene_loader.h"

namespace xval::cli {

void addExportCommand(CLI::App& app, std::function<int()>& run) {
  struct Args {
    std::string format, scene, dir;
    BudgetOptions budget;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write a scene for an external renderer.\n  pov: a self-contained POV-Ray 3.7 folder "
      "(scene.pov, scene.ini, texture.png, README.txt);\n       render it with `povray "
      "scene.ini` from that folder.\n  pov-native: the same folder with POV-Ray's own finish instead "
      "(renderer povray-native,\n       docs/povray-export.md \"Native tier\").\n  gltf: glTF 2.0 (scene.gltf, scene.bin, texture.png) with the "
      "lighting model in the scene's extras,\n       for exporters/blender/render_gltf.py.");
  cmd->add_option("format", args->format, "Target format")->required()->check(CLI::IsMember({"pov", "pov-native", "gltf"}));
  cmd->add_option("scene", args->scene, "Scene file (JSON)")->required()->check(CLI::ExistingFile);
  cmd->add_option("-o,--output", args->dir, "Output folder (created)")->required();
  addBudgetOptions(cmd, args->budget);
  cmd->callback([args, &run]() {
    run = [args]() {
      Scene scene = loadScene(args->scene, args->budget.get());
      if (args->format == "gltf") {
        GltfExport ex = exportGltf(scene, args->dir);
        std::fprintf(stderr, "xval export: wrote %s\n", ex.gltf.c_str());
        return 0;
      }
      PovExport ex = exportPov(scene, args->dir, "scene.png",
                               args->format == "pov-native" ? PovTier::Native : PovTier::Emission);
      std::fprintf(stderr, "xval export: wrote %s and %s\n", ex.pov.c_str(), ex.ini.c_str());
      return 0;
    };
  });
}

}  // namespace xval::cli
