// The Blender-import check without Blender: the registry entry and its
// refusals, the reference's geometry passes and their comparison
// (validate/geometry_check.h): identical passes pass, a loader defect's
// passes fail, and each class of the verdict is what the header says.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "blender/model_import.h"
#include "geometry/model_file.h"
#include "render/geometry_passes.h"
#include "renderers/registry.h"
#include "scene/scene_loader.h"
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
