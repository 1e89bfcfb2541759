// Robustness of the parsers that read user files (docs/robustness.md):
// limits checked before anything large is allocated or walked, and errors
// that name the file, the field and the value. The command-line side of
// the same inputs is in tests/cli (cli.bad_input.*).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/temp_files.h"
#include "scene_file/scene_generator.h"
#include "scene_file/scene_loader.h"
#include "texture/brick.h"
#include "texture/texture.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

const std::string kScene = R"({
  "name": "t",
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 8, "height": 8},
  "objects": [{"shape": "sphere"}],
  "material": {"model": {"type": "lambert"}},
  "lights": []
})";

std::string with(const std::string& from, const std::string& to) {
  std::string t = kScene;
  auto at = t.find(from);
  if (at == std::string::npos) throw std::logic_error("not in the scene: " + from);
  return t.replace(at, from.size(), to);
}

// The SceneError's message for `text`, or "(loaded)".
std::string errorOf(const std::string& text, const fs::path& file = "d/s.json") {
  try {
    parseScene(text, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(loaded)";
}

fs::path freshDir(const std::string& name) { return test::freshTempDir("xval_robust_" + name); }

#define EXPECT_HAS(msg, part) EXPECT_NE((msg).find(part), std::string::npos) << (msg)

}  // namespace

// A deep value in an unknown field: the message shows a short prefix of
// it (describeJson no longer prints, then cuts, the whole value: a
// recursive dump of 100000 nested arrays overflowed the stack).
TEST(Robustness, UnknownFieldWithADeepValueHasAShortMessage) {
  std::string deep = std::string(60, '[') + "1" + std::string(60, ']');
  std::string m = errorOf(with("\"name\": \"t\",", "\"name\": \"t\", \"extra\": " + deep + ","));
  EXPECT_HAS(m, "d/s.json: extra: unknown field (value [[[[");
  EXPECT_HAS(m, "...)");
  EXPECT_LT(m.size(), 400u) << m;
}

TEST(Robustness, DescribeJsonIsBoundedAndMatchesDumpWhenShort) {
  nlohmann::json small = {{"a", {1, 2.5, "x\"y"}}, {"b", nullptr}};
  EXPECT_EQ(describeJson(small), small.dump());
  nlohmann::json deep = 1;
  for (int i = 0; i < 100000; ++i) {
    nlohmann::json a = nlohmann::json::array();
    a.push_back(std::move(deep));
    deep = std::move(a);
  }
  std::string d = describeJson(deep);
  EXPECT_EQ(d.size(), 80u);
  EXPECT_EQ(d, std::string(77, '[') + "...");
  // A long string is cut on a character boundary (UTF-8 stays valid).
  std::string s = describeJson(nlohmann::json(std::string(200, 'a') + "\xC3\xA9"));
  EXPECT_EQ(s.size(), 80u);
  std::string u = describeJson(nlohmann::json(std::string(76, 'a') + "\xC3\xA9\xC3\xA9"));
  EXPECT_NO_THROW(nlohmann::json(u).dump()) << u;
}

TEST(Robustness, NestingDeeperThanTheLimitIsRefused) {
  std::string ok = std::string(kMaxJsonDepth - 2, '[') + std::string(kMaxJsonDepth - 2, ']');
  EXPECT_HAS(errorOf(with("\"name\": \"t\",", "\"name\": \"t\", \"x\": " + ok + ",")),
             "x: unknown field");
  std::string bomb = std::string(100000, '[') + std::string(100000, ']');
  std::string m = errorOf(with("\"name\": \"t\",", "\"name\": \"t\", \"x\": " + bomb + ","));
  EXPECT_HAS(m, "d/s.json: not valid JSON in field x[0][0]");
  EXPECT_HAS(m, "nested deeper than 64 levels");
}

TEST(Robustness, DuplicateFieldIsRefusedWithItsPath) {
  std::string m = errorOf(with("\"width\": 8", "\"width\": 8, \"width\": 9"));
  EXPECT_HAS(m, "d/s.json: not valid JSON in field camera.width: duplicate field \"width\"");
}

TEST(Robustness, NumberBeyondADoubleNamesTheFieldAndTheLiteral) {
  std::string m = errorOf(with("[0, 0, 4]", "[0, -1e400, 4]"));
  EXPECT_HAS(m, "d/s.json: not valid JSON in field camera.position[1]: number -1e400 is too large");
  EXPECT_HAS(m, "line 3");
}

TEST(Robustness, SyntaxErrorNamesTheFieldAndThePlace) {
  std::string m = errorOf(with("\"lights\": []", "\"lights\": [{\"type\": \"point\", \"position\": [1, 2,]}]"));
  EXPECT_HAS(m, "d/s.json: not valid JSON in field lights[0].position[2]");
  EXPECT_HAS(m, "line 6");
  EXPECT_HAS(errorOf(" \n\t"), "d/s.json: (top level): the file is empty");
}

TEST(Robustness, SceneNamesThatAreNotOneFolderAreRefused) {
  for (const char* bad : {"", ".", "..", "a/b", "../../escape", "/tmp/x"}) {
    std::string m = errorOf(with("\"name\": \"t\"", "\"name\": " + nlohmann::json(bad).dump()));
    EXPECT_HAS(m, "d/s.json: name: expected a name");
  }
  EXPECT_HAS(errorOf(with("\"name\": \"t\"", "\"name\": \"a\\u0000b\"")), "without '/' or NUL");
  // Characters a tool misreads in a path: Blender's separator, OpenImageIO's options.
  for (const char* bad : {"a\\\\..\\\\..\\\\up", "what?", "x?config=1"})
    EXPECT_HAS(errorOf(with("\"name\": \"t\"", "\"name\": \"" + std::string(bad) + "\"")),
               "name: expected a name without '\\' or '?'") << bad;
  // A file name that is not UTF-8 (the name defaults to the file's stem).
  EXPECT_HAS(errorOf(with("\"name\": \"t\",", ""), "d/\xff\xfe.json"), "name: expected UTF-8 text");
  EXPECT_HAS(errorOf(with("\"name\": \"t\"", "\"name\": \"" + std::string(201, 'n') + "\"")),
             "name: expected at most 200 bytes, got 201 bytes");
  // From the file name when the scene has none.
  std::string no_name = with("\"name\": \"t\",", "");
  EXPECT_HAS(errorOf(no_name, "d/...json"), "(from the file name");
  // Names that are odd but one folder still load (the exporters escape
  // them; tests/cross and tests/cli/injection render them).
  for (const char* odd : {"a b", "x\" } #declare E = 1;\n\"\"\" import os", "$(touch x); `y`", "...", ".hidden"})
    EXPECT_EQ(errorOf(with("\"name\": \"t\"", "\"name\": " + nlohmann::json(odd).dump())), "(loaded)") << odd;
}

TEST(Robustness, OversizedSceneFileIsRefusedBeforeItIsRead) {
  fs::path dir = freshDir("oversize");
  { std::ofstream(dir / "big.json") << "{"; }
  fs::resize_file(dir / "big.json", kMaxSceneFileBytes + 1);  // sparse
  try {
    loadScene(dir / "big.json");
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_HAS(std::string(e.what()), "big.json: (top level): the scene file is 67108865 bytes");
  }
}

// The loader checks the image header: not an image, too large, a volume.
TEST(Robustness, TextureHeaderIsCheckedWhenTheSceneLoads) {
  fs::path dir = freshDir("texture");
  auto scene = [&](const std::string& path) {
    return with("\"model\": {\"type\": \"lambert\"}",
                "\"model\": {\"type\": \"lambert\"}, \"texture\": {\"source\": \"image\", \"path\": " +
                    nlohmann::json(path).dump() + "}");
  };
  { std::ofstream(dir / "text.png") << "not a PNG"; }
  EXPECT_HAS(errorOf(scene("text.png"), dir / "s.json"),
             "material.texture.path: texture file \"" + (dir / "text.png").string() + "\" is not an image");
  writeTexturePng(makeBrickTexture(), dir / "brick.png");
  EXPECT_EQ(errorOf(scene("brick.png"), dir / "s.json"), "(loaded)");
  EXPECT_HAS(errorOf(scene(std::string("brick.png\0x", 11)), dir / "s.json"),
             "material.texture.path: a file path cannot contain a NUL character, got \"brick.png\\u0000x\"");
}

TEST(Robustness, TextureReaderRefusesTooManyTexelsBeforeAllocating) {
  fs::path dir = freshDir("texels");
  // A PNG header claiming 16000 x 16000 (within the side limit, beyond the
  // texel limit); without the check the reader would allocate ~3 GB.
  const char* src = XVAL_TEST_CLI_DIR "/bad_scenes/too_many_texels.png";
  try {
    loadTextureImage(src);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_HAS(std::string(e.what()), "too_many_texels.png: texture image is 16000x16000");
  }
  try {
    loadTextureImage(XVAL_TEST_CLI_DIR "/bad_scenes/huge_header.png");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_HAS(std::string(e.what()), "100000x100000");
  }
}

// Generator specs: pointer patches that would allocate or nest without
// bound, too many combinations, and names that are not one folder.
TEST(Robustness, GeneratorLimits) {
  auto spec = [](const std::string& axes, const std::string& name = "s_{a}") {
    return std::string(R"({"format": "xval-generate/1", "base": {"camera": {"position": [0,0,4], "target": [0,0,0]},
      "objects": [{"shape": "sphere"}], "material": {"model": {"type": "lambert"}}, "lights": []},
      "axes": )") + axes + ", \"name\": \"" + name + "\"}";
  };
  auto errorOfSpec = [](const std::string& text) -> std::string {
    try {
      generateScenesFromText(text, "d/spec.json");
    } catch (const SceneError& e) {
      return e.what();
    }
    return "(generated)";
  };
  EXPECT_HAS(errorOfSpec(spec(R"([{"name": "a", "values": {"v": {"/lights/5": {"type": "ambient"}}}}])")),
             "d/spec.json: axes[0].values.v: \"/lights/5\": index 5 is past the end of the array (size 0");
  EXPECT_HAS(errorOfSpec(spec(R"([{"name": "a", "values": {"v": {"/new/3": 1}}}])")), "index 3");
  // Appending (index = size, or "-") is fine.
  EXPECT_EQ(errorOfSpec(spec(R"([{"name": "a", "values": {"v": {"/lights/0": {"type": "ambient"}, "/lights/-": {"type": "ambient"}}}}])")),
            "(generated)");
  std::string deep_pointer;
  for (int i = 0; i < 100; ++i) deep_pointer += "/x";
  EXPECT_HAS(errorOfSpec(spec(R"([{"name": "a", "values": {"v": {")" + deep_pointer + R"(": 1}}}])")),
             "JSON pointer deeper than 64 levels");
  std::string axes = "[";
  for (int i = 0; i < 5; ++i)
    axes += std::string(i ? "," : "") + R"({"name": "a)" + std::to_string(i) +
            R"(", "values": {"0":{},"1":{},"2":{},"3":{},"4":{},"5":{},"6":{},"7":{},"8":{},"9":{}}})";
  axes += "]";
  EXPECT_HAS(errorOfSpec(spec(axes, "s_{a0}{a1}{a2}{a3}{a4}")), "d/spec.json: axes: more than 10000 combinations");
  EXPECT_HAS(errorOfSpec(spec(R"([{"name": "a", "values": {"..": {}}}])", "{a}")),
             "name: expected a name usable as a folder name, got \"..\"");
  std::string long_value(150, 'v');
  EXPECT_HAS(errorOfSpec(spec(R"([{"name": "a", "values": {")" + long_value + R"(": {}}}])", "{a}{a}")),
             "gives a name longer than 200 bytes");
  EXPECT_HAS(errorOfSpec(spec(R"([{"name": "a", "values": {"v": {}}}])", "{b}")), "names an axis that does not exist");
  EXPECT_HAS(errorOfSpec("{\"format\": \"xval-generate/1\", \"format\": 1}"), "duplicate field \"format\"");
}
