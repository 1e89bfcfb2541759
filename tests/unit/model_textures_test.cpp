// Texture source "model": the scene reader accepts it on mesh objects
// only, with errors naming the file and the field; each primitive of the
// model file reaches the reference renderer with its own base-colour
// texture (embedded or external; none: the material's base_color); the
// POV-Ray and glTF exports carry one texture per textured primitive.
#include <gtest/gtest.h>

#include <tiny_gltf.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "geometry/model_textures.h"
#include "geometry/scene_meshes.h"
#include "gltf/gltf_exporter.h"
#include "povray/pov_exporter.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"
#include "support/scene_errors.h"
#include "support/temp_files.h"
#include "texture/texture.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

template <class T>
std::string bytesOf(const std::vector<T>& v) {
  return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

void write(const fs::path& f, const std::string& text) {
  std::ofstream out(f, std::ios::binary);
  out << text;
}

std::string readAll(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A 1 x 1 PNG of the 8-bit colour (r, g, b).
std::string onePixelPng(const fs::path& file, unsigned char r, unsigned char g, unsigned char b) {
  Texture t;
  t.width = t.height = 1;
  t.rgb8 = {r, g, b};
  t.rgb = {r / 255.0f, g / 255.0f, b / 255.0f};
  writeTexturePng(t, file);
  return readAll(file);
}

size_t count(const std::string& text, const std::string& needle) {
  size_t n = 0;
  for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

// One glTF mesh of three primitives, unit squares 1.6 wide facing +z,
// centred at x = -2, 0, 2: the left one with material 0 (a red 1-pixel
// PNG embedded in the buffer), the middle one material 1 (an external
// green 1-pixel PNG, green.png), the right one material 2 (no texture).
// `middle_uvs` false: the middle primitive has no TEXCOORD_0.
std::string threeSquaresGltf(const fs::path& dir, bool middle_uvs) {
  const std::string red = onePixelPng(dir / "red.png", 255, 0, 0);
  onePixelPng(dir / "green.png", 0, 255, 0);
  fs::remove(dir / "red.png");  // only the embedded copy remains
  std::string bin;
  std::vector<size_t> pos;
  for (float cx : {-2.0f, 0.0f, 2.0f}) {
    pos.push_back(bin.size());
    bin += bytesOf(std::vector<float>{cx - 0.8f, -0.8f, 0, cx + 0.8f, -0.8f, 0, cx + 0.8f, 0.8f, 0, cx - 0.8f, 0.8f, 0});
  }
  const size_t uv = bin.size();
  bin += bytesOf(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 0});
  const size_t idx = bin.size();
  bin += bytesOf(std::vector<uint16_t>{0, 1, 2, 0, 2, 3});
  const size_t img = bin.size();
  bin += red;
  while (bin.size() % 4) bin.push_back('\0');
  write(dir / "squares.bin", bin);
  auto view = [](size_t off, size_t len) {
    return R"({"buffer": 0, "byteOffset": )" + std::to_string(off) + R"(, "byteLength": )" + std::to_string(len) + "}";
  };
  auto prim = [](int p, int material, bool uvs) {
    return R"({"attributes": {"POSITION": )" + std::to_string(p) + (uvs ? R"(, "TEXCOORD_0": 3)" : "") +
           R"(}, "indices": 4, "material": )" + std::to_string(material) + "}";
  };
  std::string acc;
  for (int k = 0; k < 3; ++k) {
    const float cx = -2.0f + 2.0f * k;
    acc += R"({"bufferView": )" + std::to_string(k) + R"(, "componentType": 5126, "count": 4, "type": "VEC3", "min": [)" +
           std::to_string(cx - 0.8f) + R"(, -0.8, 0], "max": [)" + std::to_string(cx + 0.8f) + R"(, 0.8, 0]},)";
  }
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"name": "squares", "mesh": 0}],
  "meshes": [{"name": "squares", "primitives": [)" +
         prim(0, 0, true) + "," + prim(1, 1, middle_uvs) + "," + prim(2, 2, true) + R"(]}],
  "materials": [{"pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
                {"pbrMetallicRoughness": {"baseColorTexture": {"index": 1}}},
                {"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 0, 1]}}],
  "textures": [{"source": 0}, {"source": 1}],
  "images": [{"bufferView": 5, "mimeType": "image/png"}, {"uri": "green.png"}],
  "buffers": [{"uri": "squares.bin", "byteLength": )" +
         std::to_string(bin.size()) + R"(}],
  "bufferViews": [)" + view(pos[0], 48) + "," + view(pos[1], 48) + "," + view(pos[2], 48) + "," + view(uv, 32) + "," +
         view(idx, 12) + "," + view(img, red.size()) + R"(],
  "accessors": [)" + acc + R"(
                {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC2"},
                {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"}]})";
}

// A 96 x 32 view of the three squares under one directional light along
// -z: Lambert with c0 = 1 gives the surface colour itself.
std::string sceneText(const std::string& objects, const std::string& material) {
  return std::string(R"({"name": "t", "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 96, "height": 32},)") +
         R"("objects": )" + objects + R"(, "material": )" + material +
         R"(, "lights": [{"type": "directional", "direction": [0, 0, -1]}]})";
}

const char* kModelMaterial =
    R"({"model": {"type": "lambert"}, "texture": {"source": "model", "filter": "nearest"}, "base_color": [0, 0, 1]})";

void expectError(const fs::path& file, const std::string& text, std::initializer_list<std::string> needles) {
  test::expectSceneError(file, text, needles);
}

class ModelTextures : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::freshTempDir("xval_model_textures_test");
    write(dir / "squares.gltf", threeSquaresGltf(dir, true));
    file = dir / "scene.json";
  }
  void TearDown() override { fs::remove_all(dir); }
  Scene squares() const { return parseScene(sceneText(R"([{"shape": "mesh", "path": "squares.gltf"}])", kModelMaterial), file); }
  fs::path dir, file;
};

}  // namespace

TEST_F(ModelTextures, SourceModelIsReadAndWritten) {
  const Scene s = parseScene(sceneText(R"([{"shape": "mesh", "path": "squares.gltf"}])", kModelMaterial), file);
  ASSERT_TRUE(s.material.texture);
  EXPECT_EQ(s.material.texture->source, TextureSpec::Source::Model);
  EXPECT_EQ(s.material.base_color, glm::dvec3(0, 0, 1));
  // The writer keeps the source and the colour of untextured primitives.
  const auto j = sceneToJson(s);
  EXPECT_EQ(j["material"]["texture"]["source"], "model");
  EXPECT_EQ(j["material"]["base_color"], nlohmann::ordered_json::array({0.0, 0.0, 1.0}));
  EXPECT_EQ(j["material"]["texture"].count("path"), 0u);
  // An object's own material may use it too.
  const Scene own = parseScene(sceneText(std::string(R"([{"shape": "sphere"}, {"shape": "mesh", "path": "squares.gltf",
      "material": )") + kModelMaterial + "}]",
                                         R"({"model": {"type": "lambert"}})"),
                               file);
  EXPECT_TRUE(usesModelTextures(own));
}

TEST_F(ModelTextures, ErrorsNameTheFileAndTheField) {
  // Only a mesh has model textures: the object's own material, or the scene's.
  expectError(file, sceneText(R"([{"shape": "sphere", "material": )" + std::string(kModelMaterial) + "}]",
                              R"({"model": {"type": "lambert"}})"),
              {"objects[0].material", "source \"model\"", "\"mesh\"", "\"sphere\""});
  expectError(file, sceneText(R"([{"shape": "mesh", "path": "squares.gltf"}, {"shape": "plane"}])", kModelMaterial),
              {"objects[1].shape", "\"plane\"", "scene's material"});
  // The source takes no path of its own.
  expectError(file,
              sceneText(R"([{"shape": "mesh", "path": "squares.gltf"}])",
                        R"({"model": {"type": "lambert"}, "texture": {"source": "model", "path": "green.png"}})"),
              {"material.texture.path"});
  expectError(file,
              sceneText(R"([{"shape": "mesh", "path": "squares.gltf"}])",
                        R"({"model": {"type": "lambert"}, "texture": {"source": "models"}})"),
              {"material.texture.source", "\"model\""});
  // A textured primitive without uvs: the model file and the primitive are named.
  write(dir / "no_uv.gltf", threeSquaresGltf(dir, false));
  expectError(file, sceneText(R"([{"shape": "mesh", "path": "no_uv.gltf"}])", kModelMaterial),
              {"objects[0].path", "no_uv.gltf", "mesh 1", "no uv coordinates"});
  // The external texture must exist.
  fs::remove(dir / "green.png");
  expectError(file, sceneText(R"([{"shape": "mesh", "path": "squares.gltf"}])", kModelMaterial),
              {"objects[0].path", "squares.gltf", "green.png"});
}

TEST_F(ModelTextures, UntexturedPrimitivesWithoutUvsAreAccepted) {
  // Under source model only the primitives the file textures need uvs: a
  // PLY without uvs or textures has the material's base_color.
  write(dir / "tri.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n");
  const Scene s = parseScene(sceneText(R"([{"shape": "mesh", "path": "tri.ply"}])", kModelMaterial), file);
  RenderOptions o = defaultOptions(s);
  o.diagnostics = false;
  const Image img = renderScene(s, o);
  const float* c = img.pixel(48, 18);
  EXPECT_EQ(c[3], 1.0f);
  EXPECT_EQ(c[0], 0.0f);
  EXPECT_EQ(c[1], 0.0f);
  EXPECT_EQ(c[2], 1.0f);
}

// The resolved scene: one object per primitive, the meshes unchanged.
TEST_F(ModelTextures, ResolvedIntoOneObjectPerPrimitive) {
  const Scene s = squares();
  const Scene r = resolveModelTextures(s);
  ASSERT_EQ(r.objects.size(), 3u);
  EXPECT_FALSE(usesModelTextures(r));
  ASSERT_TRUE(r.objects[0].material && r.objects[0].material->texture);
  EXPECT_TRUE(r.objects[0].material->texture->embedded);
  EXPECT_EQ(r.objects[0].material->texture->filter, TextureFilter::Nearest);
  ASSERT_TRUE(r.objects[1].material && r.objects[1].material->texture);
  EXPECT_EQ(r.objects[1].material->texture->path, fs::canonical(dir / "green.png"));
  ASSERT_TRUE(r.objects[2].material);
  EXPECT_FALSE(r.objects[2].material->texture);
  EXPECT_EQ(r.objects[2].material->base_color, glm::dvec3(0, 0, 1));
  const SceneMeshes a = sceneMeshes(s), b = sceneMeshes(r);
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (size_t i = 0; i < a.meshes.size(); ++i) EXPECT_EQ(a.meshes[i].positions, b.meshes[i].positions) << i;
}

// Each primitive renders with its own texture, on both paths.
TEST_F(ModelTextures, EachPrimitiveIsShadedWithItsOwnTexture) {
  const Scene s = squares();
  for (Precision p : {Precision::Float, Precision::Double}) {
    RenderOptions o = defaultOptions(s);
    o.precision = p, o.diagnostics = false;
    const Image img = renderScene(s, o);
    const float* left = img.pixel(29, 16);
    const float* middle = img.pixel(48, 16);
    const float* right = img.pixel(67, 16);
    for (const float* c : {left, middle, right}) EXPECT_EQ(c[3], 1.0f) << toString(p);
    EXPECT_EQ(glm::vec3(left[0], left[1], left[2]), glm::vec3(1, 0, 0)) << toString(p) << " embedded red";
    EXPECT_EQ(glm::vec3(middle[0], middle[1], middle[2]), glm::vec3(0, 1, 0)) << toString(p) << " external green";
    EXPECT_EQ(glm::vec3(right[0], right[1], right[2]), glm::vec3(0, 0, 1)) << toString(p) << " base_color";
  }
}

// The exports: one texture per textured primitive, holding its colour.
TEST_F(ModelTextures, ExportsCarryOneTexturePerTexturedPrimitive) {
  const Scene s = squares();
  const fs::path pov_dir = dir / "pov", gltf_dir = dir / "gltf";
  const PovExport pov = exportPov(s, pov_dir);
  const std::string sdl = readAll(pov.pov);
  EXPECT_EQ(count(sdl, "mesh2"), 3u);
  EXPECT_EQ(count(sdl, "image_map"), 2u) << sdl.substr(0, 4000);
  // The textures written, by colour.
  auto colours = [](const fs::path& folder) {
    std::multiset<std::vector<unsigned char>> out;
    for (const auto& e : fs::directory_iterator(folder))
      if (e.path().extension() == ".png" && e.path().filename().string().rfind("texture", 0) == 0)
        out.insert(loadTextureImage(e.path()).rgb8);
    return out;
  };
  const std::multiset<std::vector<unsigned char>> want{{255, 0, 0}, {0, 255, 0}};
  EXPECT_EQ(colours(pov_dir), want);

  const GltfExport g = exportGltf(s, gltf_dir);
  tinygltf::Model m;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  ASSERT_TRUE(loader.LoadASCIIFromFile(&m, &err, &warn, g.gltf.string())) << err;
  size_t textured = 0;
  std::set<int> materials;
  for (const auto& mesh : m.meshes)
    for (const auto& prim : mesh.primitives) {
      materials.insert(prim.material);
      ASSERT_GE(prim.material, 0);
      if (m.materials[size_t(prim.material)].pbrMetallicRoughness.baseColorTexture.index >= 0) ++textured;
    }
  EXPECT_EQ(materials.size(), 3u);
  EXPECT_EQ(textured, 2u);
  EXPECT_EQ(m.images.size(), 2u);
  EXPECT_EQ(colours(gltf_dir), want);
}
