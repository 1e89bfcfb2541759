// Files around scenes: what a scene folder holds besides scenes
// (nonSceneReason), and generated scenes' paths rebased to where they are
// written (sceneForFolder).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene_file/scene_generator.h"
#include "scene_file/scene_loader.h"
#include "support/temp_files.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {
void writeText(const fs::path& f, const std::string& text) {
  std::ofstream(f) << text;
}
}  // namespace

TEST(SceneFolder, OtherXvalFormatsAndToleranceFilesAreNotScenes) {
  const fs::path d = test::freshTempDir("xval-scene-folder");
  writeText(d / "spec.json", R"({"format": "xval-generate/1", "base": {}})");
  writeText(d / "engine.json", R"({"format": "xval-renderer/1", "name": "e"})");
  writeText(d / "tolerances.json", R"({"default": {"max_abs_16bit": 2, "fraction": 0.999}})");
  writeText(d / "scene.json", R"({"format": "xval-scene/1", "name": "s"})");
  writeText(d / "future.json", R"({"format": "xval-scene/9"})");
  writeText(d / "other.json", R"({"format": "glTF"})");
  writeText(d / "broken.json", R"({"format": "xval-generate/1", )");
  writeText(d / "array.json", R"([1, 2])");
  EXPECT_NE(nonSceneReason(d / "spec.json").find("\"xval-generate/1\""), std::string::npos);
  EXPECT_NE(nonSceneReason(d / "engine.json").find("\"xval-renderer/1\""), std::string::npos);
  EXPECT_EQ(nonSceneReason(d / "tolerances.json"), "a tolerance file");
  // Scenes, and anything whose loading must report its own problem.
  EXPECT_EQ(nonSceneReason(d / "scene.json"), "");
  EXPECT_EQ(nonSceneReason(d / "future.json"), "");
  EXPECT_EQ(nonSceneReason(d / "other.json"), "");
  EXPECT_EQ(nonSceneReason(d / "broken.json"), "");
  EXPECT_EQ(nonSceneReason(d / "array.json"), "");
  EXPECT_EQ(nonSceneReason(d / "missing.json"), "");
}

// A spec in spec/ naming tex/t.png, generated into out/deep/: the written
// scene names ../../spec/tex/t.png, and loads from there.
TEST(SceneFolder, GeneratedScenesKeepTheirTexturesFromTheOutputFolder) {
  const fs::path d = test::freshTempDir("xval-generate-paths");
  fs::create_directories(d / "spec" / "tex");
  fs::create_directories(d / "out" / "deep");
  fs::copy_file(fs::path(XVAL_TEST_CLI_DIR) / "scenes" / "tex4.png", d / "spec" / "tex" / "t.png");
  const std::string spec = R"({"format": "xval-generate/1", "name": "g_{f}",
    "base": {"camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 8, "height": 8},
             "objects": [{"shape": "sphere"}],
             "material": {"model": {"type": "lambert"}, "texture": {"source": "image", "path": "tex/t.png"}},
             "lights": [{"type": "directional", "direction": [0, 0, -1]}]},
    "axes": [{"name": "f", "values": {"n": {"/material/texture/filter": "nearest"}}}]})";
  writeText(d / "spec" / "s.json", spec);
  const auto scenes = generateScenes(d / "spec" / "s.json");
  ASSERT_EQ(scenes.size(), 1u);
  const auto written = sceneForFolder(scenes[0], d / "spec" / "s.json", d / "out" / "deep");
  EXPECT_EQ(written["material"]["texture"]["path"], "../../spec/tex/t.png");
  EXPECT_EQ(scenes[0].json["material"]["texture"]["path"], "tex/t.png");  // the original is kept
  writeText(d / "out" / "deep" / "g_n.json", written.dump(2));
  const Scene s = loadScene(d / "out" / "deep" / "g_n.json");
  EXPECT_EQ(fs::weakly_canonical(s.material.texture->path), fs::weakly_canonical(d / "spec" / "tex" / "t.png"));
  // Absolute paths stay as they are.
  GeneratedScene abs = scenes[0];
  abs.json["material"]["texture"]["path"] = (d / "spec" / "tex" / "t.png").string();
  EXPECT_EQ(sceneForFolder(abs, d / "spec" / "s.json", d / "out")["material"]["texture"]["path"],
            (d / "spec" / "tex" / "t.png").string());
}
