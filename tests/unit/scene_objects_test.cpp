// Scene objects: "shape": "mesh" (a model file), a per-object "material"
// and "transform". The loader's errors name the file, the field and the
// value; the meshes every renderer receives (geometry/scene_meshes.h) are
// mapped by the transform (normals by the inverse transpose, re-wound when
// mirrored); the reference renderer shades each object with its own
// material on both paths, and keeps the back faces of a model file's mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "geometry/front_faces.h"
#include "geometry/model_file.h"
#include "geometry/scene_meshes.h"
#include "geometry/transform.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"
#include "support/scene_errors.h"
#include "support/temp_files.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

// One triangle in the z = 0 plane, counter-clockwise seen from +z, with
// +z normals and uvs (an open mesh: its back is seen from -z).
const char* kTrianglePly =
    "ply\nformat ascii 1.0\nelement vertex 3\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property float s\nproperty float t\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "-1 -1 0 0 0 1 0 0\n1 -1 0 0 0 1 1 0\n0 1 0 0 0 1 0.5 1\n3 0 1 2\n";

// The same triangle without uvs.
const char* kTrianglePlyNoUv =
    "ply\nformat ascii 1.0\nelement vertex 3\n"
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
    "-1 -1 0\n1 -1 0\n0 1 0\n3 0 1 2\n";

void write(const fs::path& f, const std::string& text) {
  std::ofstream out(f, std::ios::binary);
  out << text;
}

// A scene in `dir` with the given objects JSON (and a top-level material
// unless `material` is empty).
std::string sceneText(const std::string& objects, const std::string& material =
                                                      R"({"model": {"type": "lambert"}, "base_color": [1, 0, 0]})") {
  return std::string(R"({"name": "t", "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 32, "height": 32},)") +
         R"("objects": )" + objects + (material.empty() ? "" : R"(, "material": )" + material) +
         R"(, "lights": [{"type": "directional", "direction": [0, 0, -1]}]})";
}

// Expects parseScene to fail with a message holding the file and every needle.
void expectError(const fs::path& file, const std::string& text, std::initializer_list<std::string> needles) {
  test::expectSceneError(file, text, needles);
}

class SceneObjects : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::freshTempDir("xval_scene_objects_test");
    write(dir / "tri.ply", kTrianglePly);
    write(dir / "tri_no_uv.ply", kTrianglePlyNoUv);
    file = dir / "scene.json";
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir, file;
};

}  // namespace

TEST_F(SceneObjects, MeshPathIsRelativeToTheSceneFile) {
  const Scene s = parseScene(sceneText(R"([{"shape": "mesh", "path": "tri.ply"}])"), file);
  ASSERT_EQ(s.objects.size(), 1u);
  const auto& m = std::get<MeshFile>(s.objects[0].shape);
  EXPECT_EQ(m.path, dir / "tri.ply");
  ASSERT_TRUE(m.model);
  EXPECT_EQ(m.model->triangleCount(), 1);
  const SceneMeshes sm = sceneMeshes(s);
  ASSERT_EQ(sm.meshes.size(), 1u);
  EXPECT_EQ(sm.object, std::vector<size_t>{0});
  EXPECT_EQ(sm.meshes[0].positions[1], glm::dvec3(1, -1, 0));
}

TEST_F(SceneObjects, MeshErrorsNameTheFieldAndTheFile) {
  expectError(file, sceneText(R"([{"shape": "mesh"}])"), {"objects[0].path", "required field is missing"});
  expectError(file, sceneText(R"([{"shape": "mesh", "path": "nope.ply"}])"),
              {"objects[0].path", "model file", "nope.ply", "does not exist"});
  expectError(file, sceneText(R"([{"shape": "mesh", "path": ""}])"), {"objects[0].path", "expected a file path"});
  // The loader's own message, prefixed by the field.
  write(dir / "bad.fbx", "x");
  expectError(file, sceneText(R"([{"shape": "mesh", "path": "bad.fbx"}])"),
              {"objects[0].path", "bad.fbx", "unsupported model format '.fbx'"});
  write(dir / "lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
  expectError(file, sceneText(R"([{"shape": "mesh", "path": "lines.obj"}])"),
              {"objects[0].path", "lines.obj", "no triangles"});
  // A texture on a mesh without uvs, from the scene's material or the object's.
  expectError(file,
              sceneText(R"([{"shape": "mesh", "path": "tri_no_uv.ply"}])",
                        R"({"model": {"type": "lambert"}, "texture": {"source": "brick"}})"),
              {"objects[0].path", "tri_no_uv.ply", "no uv coordinates"});
  expectError(file,
              sceneText(R"([{"shape": "sphere"}, {"shape": "mesh", "path": "tri_no_uv.ply", "material":
                        {"model": {"type": "lambert"}, "texture": {"source": "brick"}}}])"),
              {"objects[1].path", "no uv coordinates"});
  // The scene budget's triangle limit reaches the loader.
  try {
    parseScene(sceneText(R"([{"shape": "mesh", "path": "tri.ply"}])"), file, Budget{0, 1ll << 30, 4096});
    ADD_FAILURE() << "no error for a mesh over the triangle budget";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("objects[0].path"), std::string::npos) << e.what();
  }
}

TEST_F(SceneObjects, TransformErrorsNameTheMember) {
  auto obj = [](const std::string& t) { return R"([{"shape": "sphere", "transform": )" + t + "}]"; };
  expectError(file, sceneText(obj(R"({"scale": [1, 0, 1]})")), {"objects[0].transform.scale[1]", "non-zero"});
  expectError(file, sceneText(obj(R"({"scale": 0})")), {"objects[0].transform.scale[0]", "non-zero"});
  expectError(file, sceneText(obj(R"({"scale": [1, 2]})")),
              {"objects[0].transform.scale", "a number or an array of 3 numbers", "[1,2]"});
  expectError(file, sceneText(obj(R"({"scale": "big"})")), {"objects[0].transform.scale", "\"big\""});
  expectError(file, sceneText(obj(R"({"rotate": {"axis": [0, 0, 0], "angle_deg": 10}})")),
              {"objects[0].transform.rotate.axis", "no direction"});
  expectError(file, sceneText(obj(R"({"rotate": {"axis": [0, 1, 0]}})")),
              {"objects[0].transform.rotate.angle_deg", "required field is missing"});
  expectError(file, sceneText(obj(R"({"rotate": {"axis": [0, 1, 0], "angle_deg": 5, "about": 1}})")),
              {"objects[0].transform.rotate.about", "unknown field"});
  expectError(file, sceneText(obj(R"({"translate": [0, 0]})")), {"objects[0].transform.translate", "[0,0]"});
  expectError(file, sceneText(obj(R"({"shear": 1})")), {"objects[0].transform.shear", "unknown field"});
}

TEST_F(SceneObjects, MaterialErrorsAndDefault) {
  // The object's material is read with the top-level schema.
  expectError(file, sceneText(R"([{"shape": "sphere", "material": {"model": {"type": "toon"}}}])"),
              {"objects[0].material.model.type", "\"toon\""});
  // Without a top-level material every object needs its own.
  expectError(file,
              sceneText(R"([{"shape": "sphere", "material": {"model": {"type": "lambert"}}}, {"shape": "plane"}])", ""),
              {"objects[1].material", "required field is missing"});
  const Scene s = parseScene(
      sceneText(R"([{"shape": "sphere"}, {"shape": "plane", "material": {"model": {"type": "yiq_luma"}}}])"), file);
  EXPECT_FALSE(s.objects[0].material);
  ASSERT_TRUE(s.objects[1].material);
  EXPECT_TRUE(std::holds_alternative<Lambert>(materialOf(s, 0).model));
  EXPECT_TRUE(std::holds_alternative<YiqLuma>(materialOf(s, 1).model));
  // Per-object numbers are checked for the precision under their own path.
  expectError(file,
              sceneText(R"([{"shape": "sphere", "material": {"model": {"type": "classic_phong", "ks": 1e35}}}])"),
              {"objects[0].material.model.ks"});
}

TEST_F(SceneObjects, SceneWriterRoundTripsObjects) {
  const Scene s = parseScene(sceneText(R"([{"shape": "mesh", "path": "tri.ply", "transform": {"scale": [1, -2, 1],
      "rotate": {"axis": [0, 0, 1], "angle_deg": 30}, "translate": [0.5, 0, 0]}, "material": {"model": {"type": "yiq_luma"}}}])"),
                             file);
  const Scene back = parseScene(sceneToJson(s).dump(), file);
  ASSERT_EQ(back.objects.size(), 1u);
  EXPECT_EQ(std::get<MeshFile>(back.objects[0].shape).path, dir / "tri.ply");
  EXPECT_EQ(back.objects[0].transform.scale, glm::dvec3(1, -2, 1));
  EXPECT_EQ(back.objects[0].transform.rotate.angle_deg, 30.0);
  EXPECT_EQ(back.objects[0].transform.translate, glm::dvec3(0.5, 0, 0));
  ASSERT_TRUE(back.objects[0].material);
  EXPECT_TRUE(std::holds_alternative<YiqLuma>(back.objects[0].material->model));
}

// A mirrored sphere keeps outward normals and front faces outward: every
// triangle's winding normal points away from the centre and agrees with
// its vertex normals.
TEST_F(SceneObjects, MirroredObjectStaysFrontFacingOutward) {
  for (const char* scale : {"[-1, 1, 1]", "[1, 1, -2]", "[-1, -1, -1]"}) {
    const Scene s = parseScene(
        sceneText(std::string(R"([{"shape": "sphere", "transform": {"scale": )") + scale + R"(, "translate": [0.5, 0, -1]}}])"),
        file);
    const TriangleMesh m = sceneMeshes(s).meshes.at(0);
    const glm::dvec3 c(0.5, 0, -1);
    size_t inward = 0, disagree = 0;
    for (const auto& t : m.triangles) {
      const glm::dvec3 p0 = m.positions[t[0]], p1 = m.positions[t[1]], p2 = m.positions[t[2]];
      const glm::dvec3 g = glm::cross(p1 - p0, p2 - p0);
      if (glm::length(g) == 0.0) continue;
      if (glm::dot(g, (p0 + p1 + p2) / 3.0 - c) <= 0.0) ++inward;
      if (glm::dot(g, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]) <= 0.0) ++disagree;
    }
    EXPECT_EQ(inward, 0u) << scale;
    EXPECT_EQ(disagree, 0u) << scale;
  }
}

// Non-uniform scale and rotation: the traced normals are the ellipsoid's
// (the gradient R S^-2 R^T (x - t)), to float32 precision.
TEST_F(SceneObjects, NonUniformScaleNormalsAreTheEllipsoids) {
  const Scene s = parseScene(sceneText(R"([{"shape": "sphere", "transform": {"scale": [2, 0.5, 1],
      "rotate": {"axis": [1, 1, 0], "angle_deg": 40}, "translate": [0, 1, 0]}}])"),
                             file);
  const TriangleMesh m = sceneMeshes(s).meshes.at(0);
  const glm::dmat3 r = rotationMatrix({{1, 1, 0}, 40});
  const glm::dmat3 s_inv2(glm::dvec3(0.25, 0, 0), glm::dvec3(0, 4, 0), glm::dvec3(0, 0, 1));
  double worst = 0.0;
  for (size_t i = 0; i < m.positions.size(); ++i) {
    const glm::dvec3 want = glm::normalize(r * s_inv2 * glm::transpose(r) * (m.positions[i] - glm::dvec3(0, 1, 0)));
    worst = std::max(worst, glm::length(m.normals[i] - want));
  }
  EXPECT_LT(worst, 1e-5);  // float32 rounding of positions (extent 2) and normals
}

TEST_F(SceneObjects, BackFacesOfMeshesAndTransformedShapesAreNeverSkipped) {
  const glm::dvec3 eye(0, 0, 10);
  SceneObject sphere{UvSphere{}};
  const TriangleMesh sm = tessellate(sphere.shape);
  EXPECT_TRUE(objectBackFacesNeverFirstHit(sphere, sm, eye));
  sphere.transform.scale = {1, 1, -1};
  EXPECT_FALSE(objectBackFacesNeverFirstHit(sphere, sm, eye));
  const Scene s = parseScene(sceneText(R"([{"shape": "mesh", "path": "tri.ply"}])"), file);
  EXPECT_FALSE(objectBackFacesNeverFirstHit(s.objects[0], sceneMeshes(s).meshes[0], eye));
}

// The open triangle seen from behind (camera at -z): every path and
// precision draws it (a skipped back face would leave the centre empty).
TEST_F(SceneObjects, OpenMeshSeenFromBehindIsDrawnOnEveryPath) {
  std::string text = sceneText(R"([{"shape": "mesh", "path": "tri.ply"}])");
  text.replace(text.find("[0, 0, 4]"), 9, "[0, 0, -4]");
  const Scene s = parseScene(text, file);
  for (Precision p : {Precision::Float, Precision::Double})
    for (bool rasterise : {true, false}) {
      RenderOptions o = defaultOptions(s);
      o.precision = p, o.rasterise = rasterise, o.threads = 1;
      const Image img = renderScene(s, o);
      EXPECT_EQ(img.pixel(16, 16)[3], 1.0f) << toString(p) << " rasterise " << rasterise;
    }
}

// Two planes side by side: the left with the scene's red, the right with
// its own green material; both paths shade each with its own.
TEST_F(SceneObjects, EachObjectIsShadedWithItsOwnMaterial) {
  const Scene s = parseScene(
      sceneText(R"([{"shape": "plane", "center": [-1, 0, 0], "size": [1.8, 1.8]},
                    {"shape": "plane", "center": [1, 0, 0], "size": [1.8, 1.8],
                     "material": {"model": {"type": "lambert"}, "base_color": [0, 1, 0]}}])"),
      file);
  for (Precision p : {Precision::Float, Precision::Double})
    for (bool batch : {true, false}) {
      RenderOptions o = defaultOptions(s);
      o.precision = p, o.batch_shading = batch, o.diagnostics = false;
      const Image img = renderScene(s, o);
      const float* left = img.pixel(8, 16);
      const float* right = img.pixel(24, 16);
      EXPECT_EQ(left[3], 1.0f);
      EXPECT_EQ(right[3], 1.0f);
      EXPECT_GT(left[0], 0.9f) << toString(p);
      EXPECT_EQ(left[1], 0.0f) << toString(p);
      EXPECT_EQ(right[0], 0.0f) << toString(p);
      EXPECT_GT(right[1], 0.9f) << toString(p);
    }
}
