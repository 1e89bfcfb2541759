// Scene files: one test per kind of bad input; each asserts that the
// message names the file, the field path and the bad value.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"
#include "scene_file/scene_generator.h"
#include "texture/brick.h"
#include "texture/texture.h"

#include <sstream>
#include "support/temp_files.h"

using namespace xval;

namespace {

const char* kValid = R"({
  "format": "xval-scene/1",
  "name": "t",
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 64, "height": 48},
  "objects": [{"shape": "sphere"}],
  "material": {"model": {"type": "classic_phong"}},
  "lights": [{"type": "point", "position": [1, 2, 3]}]
})";

// Applies a textual substitution to the valid scene and expects a
// SceneError containing every `needles` string.
void expectError(const std::string& from, const std::string& to,
                 std::initializer_list<std::string> needles) {
  std::string text = kValid;
  auto pos = text.find(from);
  ASSERT_NE(pos, std::string::npos) << from;
  text.replace(pos, from.size(), to);
  try {
    parseScene(text, "dir/scene.json");
    FAIL() << "no error for: " << to;
  } catch (const SceneError& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("dir/scene.json"), std::string::npos) << msg;
    for (const auto& n : needles) EXPECT_NE(msg.find(n), std::string::npos) << "'" << n << "' not in: " << msg;
  }
}

}  // namespace

TEST(SceneLoader, ValidSceneLoadsWithDefaults) {
  Scene s = parseScene(kValid, "scene.json");
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.camera.width, 64);
  EXPECT_EQ(s.camera.height, 48);
  EXPECT_DOUBLE_EQ(s.camera.fov_y_deg, 45.0);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_TRUE(std::holds_alternative<UvSphere>(s.objects[0].shape));
  EXPECT_EQ(s.shading, ShadingMode::Phong);
  EXPECT_EQ(s.render.spp, 1);
  EXPECT_EQ(s.render.precision, Precision::Double);
  const auto& p = std::get<ClassicPhong>(s.material.model);
  EXPECT_DOUBLE_EQ(p.shininess, 55.0);
  EXPECT_FALSE(s.material.texture.has_value());
}

TEST(SceneLoader, TruncatedJson) {
  try {
    parseScene(std::string(kValid).substr(0, 60), "dir/scene.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("dir/scene.json: not valid JSON"), std::string::npos);
  }
}

TEST(SceneLoader, UnknownField) {
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"colour\": 3", {"colour", "unknown field"});
  expectError("{\"shape\": \"sphere\"}", "{\"shape\": \"sphere\", \"radius_m\": 2}",
              {"objects[0].radius_m", "unknown field"});
}

TEST(SceneLoader, WrongType) {
  expectError("\"width\": 64", "\"width\": \"64\"", {"camera.width", "\"64\"", "integer"});
  expectError("\"position\": [1, 2, 3]", "\"position\": [1, \"x\", 3]",
              {"lights[0].position[1]", "\"x\""});
}

TEST(SceneLoader, MissingRequiredValue) {
  expectError("\"target\": [0, 0, 0], ", "", {"camera.target", "missing"});
  expectError("\"position\": [1, 2, 3]", "\"color\": [1, 1, 1]", {"lights[0].position", "missing"});
}

TEST(SceneLoader, NanIsRejected) {
  // JSON has no NaN literal: the parser names the position.
  std::string text = kValid;
  text.replace(text.find("[1, 2, 3]"), 9, "[NaN, 2, 3]");
  try {
    parseScene(text, "dir/scene.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("dir/scene.json: not valid JSON"), std::string::npos);
  }
}

TEST(SceneLoader, NonFiniteNumberIsRejected) {
  // A literal too large for a double is rejected by the parser, with the
  // literal in the message.
  std::string text = kValid;
  text.replace(text.find("[1, 2, 3]"), 9, "[1e999, 2, 3]");
  try {
    parseScene(text, "dir/scene.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("dir/scene.json: not valid JSON"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("1e999"), std::string::npos) << e.what();
  }
}

TEST(SceneLoader, NegativeResolution) {
  expectError("\"width\": 64", "\"width\": -64", {"camera.width", "-64", "[1, 16384]"});
}

TEST(SceneLoader, AbsurdResolution) {
  expectError("\"width\": 64, \"height\": 48", "\"width\": 16384, \"height\": 16384",
              {"camera.width", "exceeds"});
}

TEST(SceneLoader, ZeroLengthDirection) {
  expectError("{\"type\": \"point\", \"position\": [1, 2, 3]}",
              "{\"type\": \"directional\", \"direction\": [0, 0, 0]}",
              {"lights[0].direction", "non-zero direction"});
}

TEST(SceneLoader, OutOfRangeNumbers) {
  expectError("\"width\": 64", "\"width\": 64, \"fov_y_deg\": 180", {"camera.fov_y_deg", "180"});
  expectError("{\"type\": \"classic_phong\"}", "{\"type\": \"classic_phong\", \"shininess\": -1}",
              {"material.model.shininess", "-1"});
  expectError("{\"type\": \"classic_phong\"}", "{\"type\": \"wrap_around\", \"factor\": 1.5}",
              {"material.model.factor", "1.5"});
}

TEST(SceneLoader, UnknownChoice) {
  expectError("{\"type\": \"classic_phong\"}", "{\"type\": \"blinn\"}",
              {"material.model.type", "\"blinn\"", "classic_phong"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"shading\": \"smooth\"", {"shading", "smooth"});
}

TEST(SceneLoader, SppMustBeAPerfectSquare) {
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"render\": {\"spp\": 8}", {"render.spp", "8", "perfect square"});
}

TEST(SceneLoader, NotAKnot) {
  expectError("{\"shape\": \"sphere\"}", "{\"shape\": \"torus_knot\", \"p\": 2, \"q\": 4}",
              {"objects[0].q", "coprime"});
}

TEST(SceneLoader, BaseColorAndTextureTogether) {
  expectError("{\"type\": \"classic_phong\"}}",
              "{\"type\": \"classic_phong\"}, \"texture\": {\"source\": \"brick\"}, \"base_color\": [1, 0, 0]}",
              {"material.base_color"});
}

TEST(SceneLoader, MissingTextureFile) {
  expectError("{\"type\": \"classic_phong\"}}",
              "{\"type\": \"classic_phong\"}, \"texture\": {\"source\": \"image\", \"path\": \"no/such.png\"}}",
              {"material.texture.path", "no/such.png", "does not exist"});
}

TEST(SceneLoader, AttenuationConstantMustBePositive) {
  expectError("\"position\": [1, 2, 3]",
              "\"position\": [1, 2, 3], \"attenuation\": {\"constant\": 0, \"quadratic\": 1}",
              {"lights[0].attenuation.constant", "> 0"});
}

TEST(SceneLoader, CameraLookingAlongUp) {
  expectError("\"target\": [0, 0, 0]", "\"target\": [0, 5, 4]", {"camera.up", "parallel"});
}

TEST(SceneLoader, MissingFileAndRelativeTexturePath) {
  EXPECT_THROW(loadScene("/no/such/scene.json"), SceneError);
  auto dir = xval::test::freshTempDir("xval_loader_test");
  std::filesystem::create_directories(dir);
  writeTexturePng(makeBrickTexture(), dir / "tex.png");  // the loader checks the header
  std::string text = kValid;
  text.replace(text.find("{\"type\": \"classic_phong\"}}"), 26,
               "{\"type\": \"classic_phong\"}, \"texture\": {\"source\": \"image\", \"path\": \"tex.png\"}}");
  { std::ofstream(dir / "s.json") << text; }
  Scene s = loadScene(dir / "s.json");
  ASSERT_TRUE(s.material.texture.has_value());
  EXPECT_EQ(s.material.texture->path, dir / "tex.png");
}

TEST(SceneLoader, EveryReferenceSceneLoads) {
  int n = 0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(XVAL_REFERENCE_DIR) + "/scenes")) {
    if (e.path().extension() != ".json") continue;
    EXPECT_NO_THROW(loadScene(e.path())) << e.path();
    ++n;
  }
  EXPECT_GE(n, 20);
}

// sceneToJson is the loader's inverse: every reference scene survives a
// write/read round trip unchanged (compared through its JSON text).
TEST(SceneWriter, RoundTripsEveryReferenceScene) {
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::string(XVAL_REFERENCE_DIR) + "/scenes")) {
    if (e.path().extension() != ".json") continue;
    Scene a = loadScene(e.path());
    std::string text = sceneToJson(a).dump();
    Scene b = parseScene(text, e.path());
    EXPECT_EQ(sceneToJson(b).dump(), text) << e.path();
    ++n;
  }
  EXPECT_GE(n, 20);
}

// The committed scenes of each spec in reference/specs that generates
// reference scenes are exactly what it generates (regenerate: xval generate
// reference/specs/SPEC.json -o reference/scenes): the Figure 1 scenes and
// the listing-literal YIQ scenes.
namespace {
void expectSpecGeneratesTheCommittedScenes(const std::string& spec, size_t count) {
  auto scenes = generateScenes(std::string(XVAL_REFERENCE_DIR) + "/specs/" + spec);
  ASSERT_EQ(scenes.size(), count) << spec;
  for (const auto& g : scenes) {
    std::ifstream in(std::string(XVAL_REFERENCE_DIR) + "/scenes/" + g.name + ".json");
    ASSERT_TRUE(in) << spec << ": " << g.name;
    std::stringstream s;
    s << in.rdbuf();
    EXPECT_EQ(s.str(), g.json.dump(2) + "\n") << spec << ": " << g.name;
  }
}
}  // namespace

TEST(SceneGenerator, Fig1SpecGeneratesTheCommittedScenes) { expectSpecGeneratesTheCommittedScenes("fig1.json", 6); }

TEST(SceneGenerator, ListingSpecGeneratesTheCommittedScenes) {
  expectSpecGeneratesTheCommittedScenes("listing.json", 3);
}

TEST(SceneGenerator, InvalidCombinationNamesTheSpecAndTheField) {
  auto dir = xval::test::freshTempDir("xval_gen_test");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "spec.json") << R"({"format": "xval-generate/1",
    "base": {"camera": {"position": [0,0,4], "target": [0,0,0]}, "objects": [{"shape": "sphere"}],
             "material": {"model": {"type": "lambert"}}, "lights": []},
    "axes": [{"name": "m", "values": {"ok": {}, "bad": {"/material/model/kd": 1}}}],
    "name": "s_{m}"})";
  try {
    generateScenes(dir / "spec.json");
    FAIL();
  } catch (const SceneError& e) {
    std::string m = e.what();
    EXPECT_NE(m.find("spec.json: combination (m=bad)"), std::string::npos) << m;
    EXPECT_NE(m.find("material.model.kd: unknown field"), std::string::npos) << m;
  }
}

TEST(SceneLoader, DeclaredTolerancesNeedAKnownRendererAndAReason) {
  expectError("\"name\": \"t\"",
              "\"name\": \"t\", \"tolerances\": {\"povray\": {\"max_abs_16bit\": 16}}",
              {"tolerances.povray.reason", "missing"});
  expectError("\"name\": \"t\"",
              "\"name\": \"t\", \"tolerances\": {\"povray\": {\"max_abs_16bit\": 16, \"reason\": \"why\"}}",
              {"tolerances.povray.reason", "written reason"});
  expectError("\"name\": \"t\"",
              "\"name\": \"t\", \"tolerances\": {\"mitsuba\": {\"reason\": \"a long enough reason here\"}}",
              {"tolerances.mitsuba", "unknown field"});
  std::string text = kValid;
  text.replace(text.find("\"name\": \"t\""), 11,
               "\"name\": \"t\", \"tolerances\": {\"blender\": {\"max_abs_16bit\": 8, \"fraction\": 0.99, "
               "\"reason\": \"float32 texture coordinates in Cycles\"}}");
  Scene s = parseScene(text, "scene.json");
  ASSERT_EQ(s.tolerances.size(), 1u);
  EXPECT_EQ(s.tolerances[0].renderer, "blender");
  EXPECT_EQ(*s.tolerances[0].max_abs_16bit, 8.0);
  EXPECT_EQ(*s.tolerances[0].fraction, 0.99);
}

TEST(SceneLoader, RenderersNameKnownRenderersOnceAtLeastTwo) {
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"renderers\": [\"reference\", \"pov\"]",
              {"renderers[1]", "unknown renderer \"pov\"", "expected one of reference, povray"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"renderers\": [\"blender\", \"reference\", \"blender\"]",
              {"renderers[2]", "\"blender\" named twice"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"renderers\": [\"reference\"]",
              {"renderers", "at least two renderers", "got 1"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"renderers\": \"reference\"", {"renderers", "an array of strings"});
  std::string text = kValid;
  text.replace(text.find("\"name\": \"t\""), 11, "\"name\": \"t\", \"renderers\": [\"blender\", \"reference\"]");
  const Scene s = parseScene(text, "scene.json");
  EXPECT_EQ(s.renderers, (std::vector<std::string>{"blender", "reference"}));
  EXPECT_TRUE(parseScene(kValid, "scene.json").renderers.empty());
  // The writer keeps the field (the generator's scenes and round trips).
  EXPECT_EQ(parseScene(sceneToJson(s).dump(), "scene.json").renderers, s.renderers);
}

// `findings`: a renderer compared against the reference, one the scene is
// meant for, with a written reason; read, checked, written back.
TEST(SceneLoader, FindingsNameAComparedRendererWithAReason) {
  const std::string why = "its built-in model is Fujii's, not the 1994 one";
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"findings\": {\"reference\": \"" + why + "\"}",
              {"findings.reference", "unknown field"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"findings\": {\"mitsuba\": \"" + why + "\"}",
              {"findings.mitsuba", "unknown field"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"findings\": {\"blender\": \"differs\"}",
              {"findings.blender", "written reason"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"findings\": {\"blender\": 3}", {"findings.blender"});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"findings\": {}", {"findings", "at least one"});
  expectError("\"name\": \"t\"",
              "\"name\": \"t\", \"renderers\": [\"reference\", \"povray\"], \"findings\": {\"blender\": \"" + why +
                  "\"}",
              {"findings.blender", "not meant for blender"});
  std::string text = kValid;
  text.replace(text.find("\"name\": \"t\""), 11,
               "\"name\": \"t\", \"renderers\": [\"reference\", \"blender\"], \"findings\": {\"blender\": \"" + why +
                   "\"}");
  const Scene s = parseScene(text, "scene.json");
  ASSERT_EQ(s.findings.size(), 1u);
  EXPECT_EQ(s.findings[0], (std::pair<std::string, std::string>{"blender", why}));
  ASSERT_NE(findingOf(s, "blender"), nullptr);
  EXPECT_EQ(*findingOf(s, "blender"), why);
  EXPECT_EQ(findingOf(s, "povray"), nullptr);
  EXPECT_TRUE(parseScene(kValid, "scene.json").findings.empty());
  EXPECT_EQ(parseScene(sceneToJson(s).dump(), "scene.json").findings, s.findings);
}

// The paper's listing's own choices: read, checked, written back.
TEST(SceneLoader, ListingOptionsNormalizeNormalAndTrilinear) {
  std::string text = kValid;
  text.replace(text.find("\"name\": \"t\""), 11, "\"name\": \"t\", \"normalize_normal\": false");
  EXPECT_FALSE(parseScene(text, "dir/scene.json").normalize_normal);
  EXPECT_TRUE(parseScene(kValid, "dir/scene.json").normalize_normal);
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"normalize_normal\": false, \"shading\": \"flat\"",
              {"normalize_normal", "phong", "\"flat\""});
  expectError("\"name\": \"t\"", "\"name\": \"t\", \"normalize_normal\": 0", {"normalize_normal", "0"});
  const std::string tri = "{\"type\": \"classic_phong\"}, \"texture\": {\"source\": \"brick\", \"filter\": \"trilinear\"}";
  text = kValid;
  text.replace(text.find("{\"type\": \"classic_phong\"}"), 25, tri);
  const Scene s = parseScene(text, "dir/scene.json");
  ASSERT_TRUE(s.material.texture);
  EXPECT_EQ(s.material.texture->filter, TextureFilter::Trilinear);
  expectError("{\"type\": \"classic_phong\"}", tri + "}, \"shading\": \"gouraud\", \"x\": {\"y\": 0",
              {"shading", "gouraud", "trilinear", "footprint"});
  expectError("{\"type\": \"classic_phong\"}", "{\"type\": \"classic_phong\"}, \"texture\": {\"source\": \"brick\", "
              "\"filter\": \"mipmap\"}", {"material.texture.filter", "\"mipmap\"", "trilinear"});
  // The writer keeps both (and writes normalize_normal only when false).
  Scene w = s;
  w.normalize_normal = false;
  const Scene back = parseScene(sceneToJson(w).dump(), "dir/scene.json");
  EXPECT_FALSE(back.normalize_normal);
  EXPECT_EQ(back.material.texture->filter, TextureFilter::Trilinear);
  EXPECT_EQ(sceneToJson(s).dump().find("normalize_normal"), std::string::npos);
}
