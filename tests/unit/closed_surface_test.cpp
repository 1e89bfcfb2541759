// Which meshes are the surface of an outward solid (geometry/
// closed_surface.h), and that skipping the back faces of those seen from
// outside leaves every pixel unchanged (geometry/front_faces.h,
// closedMeshBackFacesNeverFirstHit), while open meshes and an eye inside
// the box skip nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>

#include "geometry/closed_surface.h"
#include "geometry/front_faces.h"
#include "geometry/scene_meshes.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"
#include "support/temp_files.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

// The unit cube [0, 1]^3 with 8 shared vertices, 12 triangles wound
// counter-clockwise seen from outside.
TriangleMesh cube(glm::dvec3 origin = glm::dvec3(0.0), double size = 1.0) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.positions.push_back(origin + size * glm::dvec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  // Faces as quads (a, b, c, d) counter-clockwise from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back(glm::u32vec3(q[0], q[1], q[2]));
    m.triangles.push_back(glm::u32vec3(q[0], q[2], q[3]));
  }
  m.normals.assign(m.positions.size(), glm::dvec3(0, 0, 1));  // unused by the check
  return m;
}

// A torus about z (major radius R, tube r), nu x nv quads, the indices
// wrapping around (no seam): closed, wound outwards, float32 coordinates.
TriangleMesh torus(double R, double r, int nu, int nv, glm::dvec3 centre = glm::dvec3(0.0)) {
  TriangleMesh m;
  const double two_pi = 2.0 * std::numbers::pi;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = two_pi * i / nu, v = two_pi * j / nv;
      const glm::dvec3 p = centre + glm::dvec3((R + r * std::cos(v)) * std::cos(u),
                                               (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
      m.positions.push_back(glm::dvec3(glm::vec3(p)));
      m.normals.push_back(glm::dvec3(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)));
    }
  auto at = [&](int i, int j) { return uint32_t(((i + nu) % nu) * nv + (j + nv) % nv); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      // d/du x d/dv points outwards: (i, j), (i+1, j), (i+1, j+1), (i, j+1) runs counter-clockwise.
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

TriangleMesh join(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh m = a;
  const uint32_t o = uint32_t(a.positions.size());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  m.normals.insert(m.normals.end(), b.normals.begin(), b.normals.end());
  for (auto t : b.triangles) m.triangles.push_back(t + glm::u32vec3(o));
  return m;
}

void flip(TriangleMesh& m, size_t t) { std::swap(m.triangles[t][1], m.triangles[t][2]); }

void expectFailsWith(const TriangleMesh& m, const std::string& needle) {
  const std::string why = whyNotAnOutwardSolid(m);
  EXPECT_NE(why.find(needle), std::string::npos) << "got: \"" << why << "\", expected \"" << needle << "\"";
}

}  // namespace

TEST(ClosedSurface, CubeAndTorusAreOutwardSolids) {
  EXPECT_EQ(whyNotAnOutwardSolid(cube()), "");
  EXPECT_EQ(whyNotAnOutwardSolid(torus(1.0, 0.3, 64, 24)), "");
  // Two solids apart, and a cube well inside a torus's hole: still fine.
  EXPECT_EQ(whyNotAnOutwardSolid(join(cube(), cube(glm::dvec3(3, 0, 0)))), "");
  EXPECT_EQ(whyNotAnOutwardSolid(join(torus(2.0, 0.3, 64, 24), cube(glm::dvec3(-0.5), 1.0))), "");
}

TEST(ClosedSurface, OpenMeshIsNot) {
  TriangleMesh m = torus(1.0, 0.3, 32, 12);
  m.triangles.erase(m.triangles.begin() + 40);
  expectFailsWith(m, "not closed");
}

TEST(ClosedSurface, InconsistentWindingIsNot) {
  TriangleMesh m = cube();
  flip(m, 5);
  expectFailsWith(m, "inconsistent winding");
}

TEST(ClosedSurface, InsideOutIsNot) {
  TriangleMesh m = torus(1.0, 0.3, 32, 12);
  for (size_t t = 0; t < m.triangles.size(); ++t) flip(m, t);
  expectFailsWith(m, "not outward");
}

// A hollow box modelled as an outer wall and an inner wall turned inside
// out: each closed and embedded, but the inner component has negative
// volume (w = -1 would be possible for another such mesh): refused.
TEST(ClosedSurface, InnerWallOfAHollowSolidIsNot) {
  TriangleMesh inner = cube(glm::dvec3(0.25), 0.5);
  for (size_t t = 0; t < inner.triangles.size(); ++t) flip(inner, t);
  expectFailsWith(join(cube(), inner), "not outward");
}

TEST(ClosedSurface, IntersectingSolidsAreNot) {
  expectFailsWith(join(cube(), cube(glm::dvec3(0.5, 0.25, 0.125))), "not embedded");
  // One component crossing itself: a spindle torus (tube wider than the
  // major radius).
  expectFailsWith(torus(0.2, 0.3, 48, 24), "not embedded");
  // Touching at a corner without sharing the vertex.
  expectFailsWith(join(cube(), cube(glm::dvec3(1.0))), "not embedded");
}

TEST(ClosedSurface, FoldedOrDegenerateIsNot) {
  TriangleMesh m = cube();
  m.positions[7] = m.positions[6];  // the top face's corner moved onto its neighbour
  expectFailsWith(m, "degenerate");
  // A vertex pushed through the opposite face: the cube folds into itself.
  TriangleMesh f = cube();
  f.positions[7] = glm::dvec3(0.4, 0.5, -0.5);
  EXPECT_NE(whyNotAnOutwardSolid(f), "");
}

// A closed cone of 20,000 sides: every side meets the apex, so their
// boxes share the apex's cell (2e8 candidate pairs): the check gives up
// instead of taking quadratic time, and claims nothing.
TEST(ClosedSurface, QuadraticWorkIsRefused) {
  TriangleMesh m;
  const int n = 20000;
  m.positions.push_back({0, 0, 1});  // apex
  m.positions.push_back({0, 0, 0});  // base centre
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    m.positions.push_back(glm::dvec3(glm::vec3(std::cos(a), std::sin(a), 0.0f)));
  }
  for (uint32_t i = 0; i < uint32_t(n); ++i) {
    const uint32_t a = 2 + i, b = 2 + (i + 1) % n;
    m.triangles.push_back({0, a, b});  // side, outwards
    m.triangles.push_back({1, b, a});  // base, downwards
  }
  m.normals.assign(m.positions.size(), glm::dvec3(0, 0, 1));
  expectFailsWith(m, "not checked");
}

TEST(ClosedSurface, EyeMustBeOutsideTheBox) {
  const TriangleMesh m = torus(1.0, 0.3, 64, 24);
  EXPECT_TRUE(closedMeshBackFacesNeverFirstHit(m, {0, 0, 4}));
  EXPECT_TRUE(closedMeshBackFacesNeverFirstHit(m, {0, 0, 0.3001}));  // above the box (z <= 0.3)
  // In the hole (outside the solid, but inside the box): not claimed.
  EXPECT_FALSE(closedMeshBackFacesNeverFirstHit(m, {0, 0, 0}));
  EXPECT_FALSE(closedMeshBackFacesNeverFirstHit(m, {1, 0, 0}));  // inside the tube
  TriangleMesh open = m;
  open.triangles.pop_back();
  EXPECT_FALSE(closedMeshBackFacesNeverFirstHit(open, {0, 0, 4}));
}

namespace {

// `m` as a binary-free ASCII PLY (indices kept as they are).
void writePly(const fs::path& f, const TriangleMesh& m) {
  std::ofstream o(f);
  o.precision(9);
  o << "ply\nformat ascii 1.0\nelement vertex " << m.positions.size()
    << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << m.triangles.size()
    << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (const auto& p : m.positions) o << float(p.x) << ' ' << float(p.y) << ' ' << float(p.z) << '\n';
  for (const auto& t : m.triangles) o << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

Scene meshScene(const fs::path& dir, const std::string& objects, glm::dvec3 eye = {0.3, 0.5, 4.2}, int size = 96) {
  const fs::path file = dir / "scene.json";
  std::ofstream o(file);
  o << R"({"name": "closed", "camera": {"position": [)" << eye.x << ", " << eye.y << ", " << eye.z
    << R"(], "target": [0, 0, 0], "width": )" << size << R"(, "height": )" << size
    << R"(}, "objects": )" << objects
    << R"(, "material": {"model": {"type": "classic_phong", "variant": "paper", "shininess": 40}},
          "lights": [{"type": "point", "position": [2, 3, 4]}], "shading": "phong"})";
  o.close();
  return loadScene(file);
}

// Renders with and without skipping back faces: equal bit for bit (colour,
// alpha, every diagnostic channel); returns how many were skipped.
size_t expectSameWithAndWithoutCulling(const Scene& s, int spp, Precision precision) {
  RenderOptions with, without;
  with.precision = without.precision = precision;
  with.spp = without.spp = spp;
  with.diagnostics = without.diagnostics = true;
  without.cull_back_faces = false;
  RenderStats sw, so;
  const Image a = renderScene(s, with, &sw), b = renderScene(s, without, &so);
  EXPECT_EQ(so.culled_triangles, 0u);
  EXPECT_EQ(0, std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)));
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.backfacing, b.backfacing);
  EXPECT_EQ(a.raw, b.raw);
  return sw.culled_triangles;
}

class ClosedModelMesh : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::freshTempDir("xval_closed_surface_test");
    // Fine enough that most triangles are below a pixel at 96 x 96.
    writePly(dir / "torus.ply", torus(1.0, 0.35, 240, 60));
    TriangleMesh open = torus(1.0, 0.35, 240, 60);
    open.triangles.resize(open.triangles.size() - 2000);  // a strip of the tube removed
    writePly(dir / "open.ply", open);
  }
  fs::path dir;
};

}  // namespace

TEST_F(ClosedModelMesh, SkippingBackFacesLeavesTheImageUnchanged) {
  const Scene s = meshScene(dir, R"([{"shape": "mesh", "path": "torus.ply"}])");
  for (Precision p : {Precision::Float, Precision::Double}) {
    // About half of the 28,800 triangles face away from the eye.
    const size_t culled = expectSameWithAndWithoutCulling(s, 1, p);
    EXPECT_GT(culled, 10000u);
    EXPECT_LT(culled, 18000u);
  }
  EXPECT_GT(expectSameWithAndWithoutCulling(s, 4, Precision::Float), 10000u);
}

// A scene prepared without culling (`xval render --keep-back-faces`) does
// not run the conditions' checks at all, so neither path culls, whatever
// the frame's options say; prepared with culling, the same frame culls.
TEST_F(ClosedModelMesh, PreparedWithoutCullingChecksAndCullsNothing) {
  const Scene s = meshScene(dir, R"([{"shape": "mesh", "path": "torus.ply"}])");
  RenderOptions frame;  // cull_back_faces true
  frame.precision = Precision::Float;
  for (bool cull : {false, true}) {
    PreparedScene prepared(s, Precision::Float, cull);
    Image img(s.camera.width, s.camera.height, false);
    RenderStats stats;
    prepared.render(frame, img, &stats);
    if (cull)
      EXPECT_GT(stats.culled_triangles, 10000u);
    else
      EXPECT_EQ(stats.culled_triangles, 0u);
  }
}

// Transformed (mirrored, rotated, scaled non-uniformly, moved) next to an
// untransformed copy: the check is on the mesh as rendered.
TEST_F(ClosedModelMesh, MirroredAndTransformedObjectsToo) {
  const Scene s = meshScene(dir, R"([{"shape": "mesh", "path": "torus.ply",
      "transform": {"scale": [-0.8, 0.6, 1.1], "rotate": {"axis": [1, 1, 0], "angle_deg": 50}, "translate": [0.4, 0.2, 0]}},
      {"shape": "mesh", "path": "torus.ply", "transform": {"scale": 0.5, "translate": [-0.9, -0.6, 0.5]}}])");
  const SceneMeshes sm = sceneMeshes(s);
  ASSERT_EQ(sm.meshes.size(), 2u);
  EXPECT_EQ(whyNotAnOutwardSolid(sm.meshes[0]), "");  // the mirror re-wound its triangles
  EXPECT_GT(expectSameWithAndWithoutCulling(s, 1, Precision::Float), 20000u);
  EXPECT_GT(expectSameWithAndWithoutCulling(s, 4, Precision::Float), 20000u);
  EXPECT_GT(expectSameWithAndWithoutCulling(s, 1, Precision::Double), 20000u);
}

TEST_F(ClosedModelMesh, OpenMeshOrEyeInTheBoxSkipsNothing) {
  const Scene open = meshScene(dir, R"([{"shape": "mesh", "path": "open.ply"}])");
  EXPECT_EQ(expectSameWithAndWithoutCulling(open, 1, Precision::Float), 0u);
  EXPECT_EQ(expectSameWithAndWithoutCulling(open, 1, Precision::Double), 0u);
  // The eye in the hole of the torus, inside its box, looking at the tube.
  const Scene inside = meshScene(dir, R"([{"shape": "mesh", "path": "torus.ply"}])", {0, 0, 0.2});
  EXPECT_EQ(expectSameWithAndWithoutCulling(inside, 1, Precision::Double), 0u);
}

// Wuson (the reference scenes' model): Blender wrote it with a vertex per
// triangle corner, nearly (11,184 vertices for 3,732 triangles), so no edge is
// shared by index: not closed, its back faces are kept (welding it would
// change the rasteriser's tie rule along every edge, hence pixels).
TEST(ClosedSurface, WusonIsNotClosedByIndex) {
  const Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/mesh_wuson_ply.json");
  const SceneMeshes sm = sceneMeshes(s);
  ASSERT_EQ(sm.meshes.size(), 1u);
  expectFailsWith(sm.meshes[0], "not closed");
}
