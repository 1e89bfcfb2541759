// POV-Ray renders the export of a scene whose strings are SDL, and the
// result matches the reference renderer (the strings changed nothing).
#include <gtest/gtest.h>

#include <filesystem>

#include "image/compare.h"
#include "povray/pov_render.h"
#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "texture/brick.h"

using namespace xval;
namespace fs = std::filesystem;

TEST(PovrayCross, HostileTexturePathAndNameRenderCorrectly) {
  fs::path dir = fs::temp_directory_path() / "xval_cross_inject";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string evil = "q\"uote } #declare Evil = 1;\n#end\n.png";
  writeTexturePng(makeBrickTexture(), dir / evil);
  nlohmann::json j = {
      {"name", "n\" } #declare E = 2;\n"},
      {"camera", {{"position", {0, 0, 3.5}}, {"target", {0, 0, 0}}, {"width", 96}, {"height", 96}}},
      {"objects", {{{"shape", "sphere"}}}},
      {"material",
       {{"model", {{"type", "lambert"}}},
        {"texture", {{"source", "image"}, {"path", evil}, {"filter", "bilinear"}}}}},
      {"lights", {{{"type", "directional"}, {"direction", {-0.3, -0.4, -1}}}}}};
  Scene s = parseScene(j.dump(), dir / "scene.json");
  Image ref = renderScene(s, RenderOptions{});
  Image pov = renderWithPovray(s, dir / "work", 600.0);
  Tolerance t;
  CompareMetrics m = compareImages(ref, pov, t);
  EXPECT_TRUE(t.passes(m)) << toJson(m, t);
  EXPECT_GT(m.covered_both, 1000);
}
