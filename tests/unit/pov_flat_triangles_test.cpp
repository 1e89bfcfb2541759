// POV-Ray's mesh2 shades a triangle whose three normals are equal with its
// face normal (exporters/povray/flat_triangles.h): which triangles it takes
// as flat, how far their normals are from the face normal, and the export's
// refusal when that is beyond the bound.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "povray/flat_triangles.h"
#include "povray/pov_exporter.h"
#include "scene_file/scene_loader.h"
#include "support/temp_files.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

// One triangle in the z = 0 plane (face normal +z), its three normals given.
TriangleMesh oneTriangle(glm::dvec3 n1, glm::dvec3 n2, glm::dvec3 n3) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  m.normals = {glm::normalize(n1), glm::normalize(n2), glm::normalize(n3)};
  m.uvs.assign(3, glm::dvec2(0));
  m.triangles = {{0, 1, 2}};
  return m;
}

glm::dvec3 tilted(double rad) { return {std::sin(rad), 0.0, std::cos(rad)}; }

const fs::path kStl = "/usr/share/assimp/models/STL/";

fs::path sceneWith(const fs::path& dir, const fs::path& model, const std::string& shading) {
  const fs::path f = dir / ("scene_" + shading + ".json");
  std::ofstream(f) << R"({"format": "xval-scene/1", "name": "flat",
    "camera": {"position": [1.5, 1.5, 8], "target": [1.5, 1.5, 1.5], "width": 32, "height": 32},
    "objects": [{"shape": "mesh", "path": ")" << model.string() << R"("}],
    "material": {"model": {"type": "classic_phong", "variant": "paper", "shininess": 20}},
    "lights": [{"type": "point", "position": [2, 3, 8]}], "shading": ")" << shading << R"("})";
  return f;
}

}  // namespace

TEST(PovFlatTriangles, EqualNormalsOnTheFaceAreFlatAndAgree) {
  const PovFlatTriangles f = povFlatTriangles(oneTriangle({0, 0, 1}, {0, 0, 1}, {0, 0, 1}));
  EXPECT_EQ(f.flat, 1u);
  EXPECT_EQ(f.off_face, 0u);
  EXPECT_LT(f.max_angle_rad, 1e-12);
  // Facing away is the same line: POV-Ray turns it towards the viewer.
  EXPECT_EQ(povFlatTriangles(oneTriangle({0, 0, -1}, {0, 0, -1}, {0, 0, -1})).off_face, 0u);
}

TEST(PovFlatTriangles, EqualNormalsOffTheFaceBeyondTheBoundAreCounted) {
  const PovFlatTriangles f = povFlatTriangles(oneTriangle(tilted(0.01), tilted(0.01), tilted(0.01)));
  EXPECT_EQ(f.flat, 1u);
  EXPECT_EQ(f.off_face, 1u);
  EXPECT_NEAR(f.max_angle_rad, 0.01, 1e-9);
  EXPECT_EQ(f.worst, 0u);
  // Within the bound: flat, not counted.
  const double within = kPovFlatNormalBoundRad / 2;
  EXPECT_EQ(povFlatTriangles(oneTriangle(tilted(within), tilted(within), tilted(within))).off_face, 0u);
  EXPECT_EQ(povFlatTriangles(oneTriangle(tilted(2 * kPovFlatNormalBoundRad), tilted(2 * kPovFlatNormalBoundRad),
                                         tilted(2 * kPovFlatNormalBoundRad)))
                .off_face,
            1u);
}

// POV-Ray's test is |n1 - n2|^2 <= 1e-10 on the normalised normals: 5e-6
// apart is still flat, 2e-5 apart is smooth (interpolated, as the reference).
TEST(PovFlatTriangles, NearlyEqualNormalsAreFlatUnequalOnesSmooth) {
  const double t = 0.01;
  EXPECT_EQ(povFlatTriangles(oneTriangle(tilted(t), tilted(t + 5e-6), tilted(t))).flat, 1u);
  const PovFlatTriangles smooth = povFlatTriangles(oneTriangle(tilted(t), tilted(t + 2e-5), tilted(t)));
  EXPECT_EQ(smooth.flat, 0u);
  EXPECT_EQ(smooth.off_face, 0u);
}

// assimp-testmodels' sphereWithHole.stl stores its facet normals with two
// decimals (up to 6.8e-3 rad off the faces): refused in Phong shading, where
// the normals are written, naming the file; Gouraud and flat shading write
// none and are not refused. Wuson.stl's facet normals are its faces'.
TEST(PovFlatTriangles, ExportRefusesCoarselyRoundedFacetNormals) {
  const fs::path dir = test::freshTempDir("xval_pov_flat");
  const Scene phong = loadScene(sceneWith(dir, kStl / "sphereWithHole.stl", "phong"));
  try {
    exportPov(phong, dir / "phong");
    FAIL() << "exported";
  } catch (const ExportError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("sphereWithHole.stl"), std::string::npos) << what;
    EXPECT_NE(what.find("face normal"), std::string::npos) << what;
  }
  EXPECT_NO_THROW(exportPov(loadScene(sceneWith(dir, kStl / "sphereWithHole.stl", "gouraud")), dir / "gouraud"));
  EXPECT_NO_THROW(exportPov(loadScene(sceneWith(dir, kStl / "sphereWithHole.stl", "flat")), dir / "flat"));
  EXPECT_NO_THROW(exportPov(loadScene(sceneWith(dir, kStl / "Wuson.stl", "phong")), dir / "wuson"));
}
