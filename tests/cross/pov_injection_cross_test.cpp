// POV-Ray and Blender render the exports of a scene whose strings are SDL
// and Python, and the results match the reference renderer (the strings
// changed nothing).
#include <gtest/gtest.h>

#include "validate/tolerances.h"

#include <filesystem>

#include "image/compare.h"
#include "blender/blender_render.h"
#include "povray/pov_render.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"
#include "texture/brick.h"
#include "support/temp_files.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {
Scene hostileScene(const fs::path& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string evil = "q\"uote } #declare Evil = 1;\n#end\n__import__('os').system('false')'.png";
  writeTexturePng(makeBrickTexture(), dir / evil);
  nlohmann::json j = {
      {"name", "n\" } #declare E = 2;\n\"\"\"; import os; os._exit(3) #"},
      {"camera", {{"position", {0, 0, 3.5}}, {"target", {0, 0, 0}}, {"width", 96}, {"height", 96}}},
      {"objects", {{{"shape", "sphere"}}}},
      {"material",
       {{"model", {{"type", "lambert"}}},
        {"texture", {{"source", "image"}, {"path", evil}, {"filter", "nearest"}}}}},
      {"lights", {{{"type", "directional"}, {"direction", {-0.3, -0.4, -1}}}}}};
  return parseScene(j.dump(), dir / "scene.json");
}
}  // namespace

TEST(PovrayCross, HostileTexturePathAndNameRenderCorrectly) {
  const fs::path dir = test::freshTempDir("xval_cross_inject_pov");
  Scene s = hostileScene(dir);
  Image ref = renderScene(s, RenderOptions{});
  Image pov = renderWithPovray("povray", s, dir / "work", 600.0);
  // The default tolerance (reference/tolerances.json, the toolkit's own).
  const Tolerance t = loadTolerances(toolkitToleranceFile()).default_tolerance;
  CompareMetrics m = compareImages(ref, pov, t);
  EXPECT_TRUE(t.passes(m)) << toJson(m, t);
  EXPECT_GT(m.covered_both, 1000);
}

TEST(BlenderCross, HostileTexturePathAndNameRenderCorrectly) {
  const fs::path dir = test::freshTempDir("xval_cross_inject_blender");
  Scene s = hostileScene(dir);
  Image ref = renderScene(s, RenderOptions{});
  Image bl = renderWithBlender("blender", s, dir / "work", 600.0);
  // The default tolerance (reference/tolerances.json, the toolkit's own).
  const Tolerance t = loadTolerances(toolkitToleranceFile()).default_tolerance;
  CompareMetrics m = compareImages(ref, bl, t);
  EXPECT_TRUE(t.passes(m)) << toJson(m, t);
  EXPECT_GT(m.covered_both, 1000);
}
