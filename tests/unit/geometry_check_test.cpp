// The Blender-import check without Blender: the registry entry and its
// refusals, the reference's geometry passes and their comparison
// (validate/geometry_check.h): identical passes pass, a loader defect's
// passes fail, and each class of the verdict is what the header says.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "blender/model_import.h"
#include "geometry/model_file.h"
#include "render/geometry_passes.h"
#include "renderers/registry.h"
#include "scene_file/scene_loader.h"
#include "validate/geometry_check.h"

using namespace xval;
using validation::compareGeometry;
namespace fs = std::filesystem;

namespace {
Scene referenceScene(const std::string& name) {
  return loadScene((fs::path(XVAL_REFERENCE_DIR) / "scenes" / (name + ".json")).string());
}
}  // namespace

TEST(GeometryCheck, RegistryEntryIsAGeometryCheckWithoutGoldenSet) {
  const auto& reg = renderers::registry();
  const renderers::Renderer* r = reg.find("blender-import");
  ASSERT_NE(r, nullptr);
  EXPECT_FALSE(r->every_scene);
  EXPECT_TRUE(r->geometry_passes);
  EXPECT_EQ(reg.find("golden-blender-import"), nullptr);
  EXPECT_EQ(r->cannot_express(referenceScene("mesh_wuson_ply")), "");
  EXPECT_EQ(r->cannot_express(referenceScene("mesh_boxtextured_glb")), "");
  const std::string knot = r->cannot_express(referenceScene("table2_knot_yiq"));
  EXPECT_NE(knot.find("objects[0]: a built-in shape"), std::string::npos) << knot;
}

TEST(GeometryCheck, OffIsRefusedWithTheReason) {
  const fs::path dir = fs::temp_directory_path() / ("xval_geometry_check_off_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "quad.off") << "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  const Scene s = parseScene(R"({"camera": {"position": [0.5, 0.5, 3], "target": [0.5, 0.5, 0], "width": 16,
      "height": 16}, "objects": [{"shape": "mesh", "path": "quad.off"}], "material": {"model": {"type": "lambert"}},
      "lights": [{"type": "directional", "direction": [0, 0, -1]}]})",
                             dir / "scene.json");
  try {
    checkModelImportScene(s);
    ADD_FAILURE() << "OFF not refused";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find("Blender 3.4 has no importer"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// Blender's importers open every file a model names, where our loader
// opens only the buffers and the mtl (issue #34.5): a glTF whose normal
// map (or any other uri) or an OBJ material whose bump map names a file
// outside the model's folder is refused before Blender starts. The target
// is a FIFO: an importer that opened it would hang. `blender` on PATH is
// a script that leaves a marker, so a start is seen.
class ModelImportNames : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("xval_geometry_check_names_" + std::to_string(getpid()));
    fs::remove_all(root_);
    fs::create_directories(root_ / "set");
    fs::create_directories(root_ / "outside");
    fs::create_directories(root_ / "bin");
    fifo_ = root_ / "outside" / "fifo.png";
    ASSERT_EQ(mkfifo(fifo_.c_str(), 0600), 0);
    const std::vector<float> tri{0, 0, 0, 1, 0, 0, 0, 1, 0};
    std::ofstream(root_ / "set" / "tri.bin", std::ios::binary)
        .write(reinterpret_cast<const char*>(tri.data()), std::streamsize(tri.size() * sizeof(float)));
    marker_ = root_ / "blender-started";
    std::ofstream(root_ / "bin" / "blender") << "#!/bin/sh\ntouch '" << marker_.string() << "'\n";
    fs::permissions(root_ / "bin" / "blender", fs::perms::owner_all);
    const char* path = std::getenv("PATH");
    old_path_ = path ? path : "";
    setenv("PATH", ((root_ / "bin").string() + ":/usr/bin:/bin").c_str(), 1);
  }
  void TearDown() override {
    setenv("PATH", old_path_.c_str(), 1);
    fs::remove_all(root_);
  }
  Scene sceneOf(const std::string& model) {
    return parseScene(R"({"camera": {"position": [0.3, 0.3, 3], "target": [0.3, 0.3, 0], "width": 8,
        "height": 8}, "objects": [{"shape": "mesh", "path": ")" + model + R"("}],
        "material": {"model": {"type": "lambert"}}, "lights": [{"type": "directional", "direction": [0, 0, -1]}]})",
                      root_ / "set" / "scene.json");
  }
  // A triangle whose material's normal map is image 0 at `image_uri`.
  fs::path gltf(const std::string& name, const std::string& image_uri, const std::string& buffer_uri = "tri.bin") {
    const fs::path f = root_ / "set" / name;
    std::ofstream(f) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
      "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "material": 0}]}],
      "materials": [{"normalTexture": {"index": 0}}], "textures": [{"source": 0}],
      "images": [{"uri": ")" << image_uri << R"("}],
      "buffers": [{"uri": ")" << buffer_uri << R"(", "byteLength": 36}],
      "bufferViews": [{"buffer": 0, "byteLength": 36}],
      "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                     "min": [0, 0, 0], "max": [1, 1, 0]}]})";
    return f;
  }
  // The check refuses the scene naming `field` and `value`, and Blender is
  // never started on it.
  void expectRefused(const Scene& s, const std::string& field, const std::string& value) {
    const std::string why = renderers::registry().find("blender-import")->cannot_express(s);
    EXPECT_NE(why.find(field + ": '" + value + "'"), std::string::npos) << why;
    fs::create_directories(root_ / "work");
    try {
      renderModelImport("blender-import", s, root_ / "work", 30.0);
      ADD_FAILURE() << "not refused: " << field << " " << value;
    } catch (const ExportError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "not refused before Blender: " << e.what();
    }
    EXPECT_FALSE(fs::exists(marker_)) << "Blender was started on " << field << " " << value;
    fs::remove(marker_);
  }
  fs::path root_, fifo_, marker_;
  std::string old_path_;
};

TEST_F(ModelImportNames, GltfUrisOutsideTheFolderAreRefusedBeforeBlenderStarts) {
  // The loader reads the file (it does not open a normal map) ...
  gltf("inside.gltf", "tri.bin");
  EXPECT_EQ(renderers::registry().find("blender-import")->cannot_express(sceneOf("inside.gltf")), "");
  // ... the check refuses each name outside: absolute, a ".." escape, a
  // percent-encoded one, a file: URL.
  gltf("absolute.gltf", fifo_.string());
  expectRefused(sceneOf("absolute.gltf"), "images[0].uri", fifo_.string());
  gltf("dotdot.gltf", "../outside/fifo.png");
  expectRefused(sceneOf("dotdot.gltf"), "images[0].uri", "../outside/fifo.png");
  gltf("encoded.gltf", "%2e%2e/outside/fifo.png");
  expectRefused(sceneOf("encoded.gltf"), "images[0].uri", "%2e%2e/outside/fifo.png");
  gltf("url.gltf", "file://" + fifo_.string());
  expectRefused(sceneOf("url.gltf"), "images[0].uri", "file://" + fifo_.string());
  // A buffer outside: the loader itself refuses the file (an error, not a
  // verdict of the check), before any renderer.
  for (const std::string& uri : {fifo_.string(), std::string("../outside/fifo.png")}) {
    gltf("buffer.gltf", "tri.bin", uri);
    try {
      sceneOf("buffer.gltf");
      ADD_FAILURE() << "a buffer at " << uri << " loaded";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find("buffers[0].uri"), std::string::npos) << e.what();
    }
  }
}

TEST_F(ModelImportNames, ObjMaterialMapsOutsideTheFolderAreRefusedBeforeBlenderStarts) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n";
  std::ofstream(root_ / "set" / "m.mtl") << "newmtl m\nKd 1 1 1\nmap_Kd tri.bin\nmap_Bump -bm 0.5 " << fifo_.string()
                                         << "\n";
  std::ofstream(root_ / "set" / "bump.obj") << "mtllib m.mtl\nusemtl m\n" << tri;
  expectRefused(sceneOf("bump.obj"), "map_Bump", fifo_.string());
  // The mtl itself outside the folder (absolute, a ".." escape): the loader
  // refuses the file itself (Assimp opens the mtl), an error before any
  // renderer.
  std::ofstream(root_ / "outside" / "far.mtl") << "newmtl m\nKd 1 1 1\n";
  for (const std::string& mtl : {(root_ / "outside" / "far.mtl").string(), std::string("../outside/far.mtl")}) {
    std::ofstream(root_ / "set" / "far.obj") << "mtllib " << mtl << "\nusemtl m\n" << tri;
    try {
      sceneOf("far.obj");
      ADD_FAILURE() << "an mtl at " << mtl << " loaded";
    } catch (const std::exception& e) {
      EXPECT_NE(std::string(e.what()).find("refers to a file that cannot be read"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("far.mtl"), std::string::npos) << e.what();
    }
  }
}

TEST(GeometryCheck, ReferencePassesAreViewAxisDepthAndSceneUv) {
  const Scene s = referenceScene("mesh_boxtextured_gltf");
  const GeometryPasses g = referenceGeometryPasses(s);
  ASSERT_EQ(g.width, s.camera.width);
  long long hits = 0;
  for (size_t p = 0; p < g.size(); ++p)
    if (g.hit[p] > 0.5f) {
      ++hits;
      EXPECT_EQ(g.object[p], 0);
      EXPECT_GT(g.depth[p], 0.0f);
      EXPECT_EQ(g.has_uv[p], 1.0f);
    } else {
      EXPECT_EQ(g.object[p], -1);
    }
  EXPECT_GT(hits, 10000);
  // The image encoding reads back as written.
  const GeometryPasses back = geometryPassesFromImage(toImage(g));
  EXPECT_EQ(back.object, g.object);
  EXPECT_EQ(back.u, g.u);
  EXPECT_EQ(back.depth, g.depth);
  EXPECT_TRUE(compareGeometry(g, back).pass);
}

TEST(GeometryCheck, EachConditionFails) {
  const GeometryPasses r = referenceGeometryPasses(referenceScene("mesh_wuson_ply"));
  ASSERT_TRUE(compareGeometry(r, r).pass);
  // The first covered pixel whose neighbourhood is all covered (off the
  // silhouette and, on Wuson, well inside).
  size_t inside = 0;
  for (int y = 1; y + 1 < r.height && !inside; ++y)
    for (int x = 1; x + 1 < r.width && !inside; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) all = all && r.hit[size_t(y + dy) * r.width + x + dx] > 0.5f;
      if (all) inside = size_t(y) * r.width + x;
    }
  ASSERT_NE(inside, 0u);
  {
    GeometryPasses b = r;
    b.hit[inside] = 0.0f;
    const auto m = compareGeometry(r, b);
    EXPECT_FALSE(m.pass);
    EXPECT_EQ(m.mask_off, 1);
    EXPECT_EQ(m.mask_off_silhouette, 0);
  }
  {
    GeometryPasses b = r;
    b.object[inside] = 1;
    EXPECT_FALSE(compareGeometry(r, b).pass);
  }
  {
    // One relative depth error just over the bound, on every covered pixel.
    GeometryPasses b = r;
    for (size_t p = 0; p < b.size(); ++p) b.depth[p] *= float(1.0 + 2.0 * validation::kGeometryTolerance.max_depth_rel);
    const auto m = compareGeometry(r, b);
    EXPECT_FALSE(m.pass);
    EXPECT_GT(m.max_depth_rel, validation::kGeometryTolerance.max_depth_rel);
  }
  {
    GeometryPasses b = r;
    for (size_t p = 0; p < b.size(); ++p) b.v[p] += float(2.0 * validation::kGeometryTolerance.max_uv);
    EXPECT_FALSE(compareGeometry(r, b).pass);
  }
  {
    // The whole image missed: nothing compared is no pass.
    GeometryPasses none(r.width, r.height);
    EXPECT_FALSE(compareGeometry(none, none).pass);
  }
}

// The preview of a geometry check's passes (passesPreview) shows the shape
// where the uv says nothing: Blender's UV pass of a model without uvs (an
// STL) is u = 0, v = 1 at every hit, which the uv colours alone made all
// black. Every hit pixel is visibly blue, nearer ones brighter; a miss is
// black.
TEST(GeometryCheck, PreviewShowsTheShapeWhereTheUvIsConstant) {
  GeometryPasses g = referenceGeometryPasses(referenceScene("mesh_wuson_stl"));
  size_t nearest = 0, farthest = 0, hits = 0;
  for (size_t p = 0; p < g.size(); ++p) {
    if (g.hit[p] < 0.5f) continue;
    g.u[p] = 0.0f, g.v[p] = 1.0f, g.has_uv[p] = 1.0f;  // as blender/model_import.cpp reads such a pass
    if (hits++ == 0 || g.depth[p] < g.depth[nearest]) nearest = p;
    if (g.depth[p] > g.depth[farthest] || g.hit[farthest] < 0.5f) farthest = p;
  }
  ASSERT_GT(hits, 1000u);
  ASSERT_LT(g.depth[nearest], g.depth[farthest]);
  const Image img = passesPreview(g);
  for (size_t p = 0; p < g.size(); ++p) {
    const float* px = &img.rgba[p * 4];
    if (g.hit[p] > 0.5f)
      ASSERT_GE(px[2], 0.25f) << "hit pixel " << p << " is not visible";
    else
      ASSERT_EQ(px[0] + px[1] + px[2], 0.0f) << "miss pixel " << p;
  }
  EXPECT_FLOAT_EQ(img.rgba[nearest * 4 + 2], 1.0f);
  EXPECT_FLOAT_EQ(img.rgba[farthest * 4 + 2], 0.25f);
}
