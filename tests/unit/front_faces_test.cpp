// When back faces may be skipped (geometry/front_faces.h), and that
// skipping them leaves every pixel of the fast path unchanged.
#include <gtest/gtest.h>

#include <cstring>

#include "geometry/front_faces.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"

using namespace xval;

TEST(FrontFaces, SphereOnlyFromOutside) {
  UvSphere s;
  s.center = {1, 0, 0}, s.radius = 2.0;
  const TriangleMesh m = tessellate(s);
  EXPECT_TRUE(backFacesNeverFirstHit(s, m, {1, 0, 5}));
  EXPECT_TRUE(backFacesNeverFirstHit(s, m, {1, 0, 2.01}));
  EXPECT_FALSE(backFacesNeverFirstHit(s, m, {1, 0, 2.0}));  // on the sphere
  EXPECT_FALSE(backFacesNeverFirstHit(s, m, {1, 0, 0.5}));  // inside
}

// A small sphere far from the origin: rounding to float collapses its
// vertices (zero-area triangles, coincident twins): not a solid's surface.
TEST(FrontFaces, SphereCollapsedByRoundingNever) {
  UvSphere s;
  s.center = glm::dvec3(1e6), s.radius = 0.05;
  EXPECT_FALSE(backFacesNeverFirstHit(s, tessellate(s), s.center + glm::dvec3(0.125, 0.0625, 0.375)));
  // The same place, large enough that its shortest edge (near the poles,
  // ~0.0096 r) is over 1000 x the rounding (2^-23 x 1.1e6 = 0.13): fine.
  s.radius = 1e5;
  EXPECT_TRUE(backFacesNeverFirstHit(s, tessellate(s), s.center + glm::dvec3(0, 0, 3e5)));
}

TEST(FrontFaces, PlaneNever) {
  Plane p;
  EXPECT_FALSE(backFacesNeverFirstHit(p, tessellate(p), {0, 0, 5}));
}

TEST(FrontFaces, TorusKnotFromOutsideAndNotFromInsideTheTube) {
  TorusKnot k;  // the paper's knot: tube 0.22, smallest radius of curvature ~0.74
  const TriangleMesh m = tessellate(k);
  EXPECT_TRUE(backFacesNeverFirstHit(k, m, {0, 0, 4.2}));
  // The centre line at t = 0 is (R + r, 0, 0) = (1.45, 0, 0): a point
  // inside the tube, one on the tube, and one just outside the margin.
  EXPECT_FALSE(backFacesNeverFirstHit(k, m, {1.45, 0, 0}));
  EXPECT_FALSE(backFacesNeverFirstHit(k, m, {1.45 + 0.22, 0, 0}));
  EXPECT_TRUE(backFacesNeverFirstHit(k, m, {1.45 + 0.3, 0, 0}));
  // The centre of the torus is outside the tube (and is seen from there).
  EXPECT_TRUE(backFacesNeverFirstHit(k, m, {0, 0, 0}));
}

TEST(FrontFaces, TorusKnotThatFoldsOverItselfNever) {
  TorusKnot k;
  k.tube_radius = 0.8;  // more than the centre line's smallest radius of curvature
  EXPECT_FALSE(backFacesNeverFirstHit(k, tessellate(k), {0, 0, 10}));
}

TEST(FrontFaces, WindingAgainstTheNormalsNever) {
  UvSphere s;
  TriangleMesh m = tessellate(s);
  EXPECT_TRUE(backFacesNeverFirstHit(s, m, {0, 0, 5}));
  std::swap(m.triangles[7][1], m.triangles[7][2]);  // one triangle turned inside out
  EXPECT_FALSE(backFacesNeverFirstHit(s, m, {0, 0, 5}));
}

namespace {
// Renders with and without skipping back faces; the images must be equal
// bit for bit (final colour and alpha, and every diagnostic channel).
void expectSameWithAndWithoutCulling(const Scene& s, int spp, size_t expect_culled_min,
                                     size_t expect_culled_max, Precision precision = Precision::Float) {
  RenderOptions with, without;
  with.precision = without.precision = precision;
  with.spp = without.spp = spp;
  without.cull_back_faces = false;
  RenderStats sw, so;
  const Image a = renderScene(s, with, &sw), b = renderScene(s, without, &so);
  EXPECT_STREQ(sw.visibility, precision == Precision::Float ? "rasterised"
                                                            : "Embree 16-ray packets, double-precision watertight test");
  EXPECT_EQ(so.culled_triangles, 0u);
  EXPECT_GE(sw.culled_triangles, expect_culled_min);
  EXPECT_LE(sw.culled_triangles, expect_culled_max);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  EXPECT_EQ(0, std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)));
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.backfacing, b.backfacing);
  EXPECT_EQ(a.raw, b.raw);
}
}  // namespace

TEST(FrontFaces, SkippingBackFacesLeavesTheTable2KnotUnchanged) {
  const Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json");
  // About half of the 61,440 triangles face away from the eye.
  expectSameWithAndWithoutCulling(s, 1, 20000, 40000);
}

// The reference path leaves the same back faces out of its BVH.
TEST(FrontFaces, LeavingBackFacesOutOfTheBvhLeavesTheTable2KnotUnchanged) {
  const Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json");
  expectSameWithAndWithoutCulling(s, 1, 20000, 40000, Precision::Double);
}

TEST(FrontFaces, SkippingBackFacesLeavesASphereUnchangedAt4Spp) {
  Scene s;
  s.camera.width = s.camera.height = 96;
  UvSphere sphere;
  sphere.radius = 1.5;
  s.objects = {sphere};
  s.lights = {PointLight{{1, 2, 3}, glm::dvec3(1.0), {}}};
  // 64 x 62 triangles; from 4.2 away the eye sees a cap of (1 - 1.5/4.2)/2
  // = 32% of the sphere, so about two thirds face away.
  expectSameWithAndWithoutCulling(s, 4, 2400, 3200);
  expectSameWithAndWithoutCulling(s, 4, 2400, 3200, Precision::Double);
}

// An open plane seen from behind: rasterised, nothing skipped, drawn.
TEST(FrontFaces, APlaneSeenFromBehindIsDrawn) {
  Scene s;
  s.camera.width = s.camera.height = 64;
  Plane p;
  p.normal = {0, 0, -1};  // facing away from the eye at +z
  s.objects = {p};
  s.lights = {DirectionalLight{{0, 0, -1}, glm::dvec3(1.0)}};
  RenderOptions o;
  o.precision = Precision::Float;
  RenderStats st;
  const Image img = renderScene(s, o, &st);
  EXPECT_STREQ(st.visibility, "rasterised");
  EXPECT_EQ(st.culled_triangles, 0u);
  EXPECT_EQ(img.pixel(32, 32)[3], 1.0f);
}

// The BVH's twin of the raster test (trianglesNotFacingAway): a triangle
// is left out only when it clearly faces away from the eye, g . (eye - P0)
// < -1e-9 |g| |eye - P0| (condition 3).
TEST(FrontFaces, BvhLeavesOutOnlyTrianglesClearlyFacingAway) {
  const glm::dvec3 p0{0, 0, 0}, p1{1, 0, 0}, p2{0, 1, 0};  // g = +z
  EXPECT_FALSE(facesAwayFromEye(p0, p1, p2, {0.2, 0.2, 5}));   // in front
  EXPECT_TRUE(facesAwayFromEye(p0, p1, p2, {0.2, 0.2, -5}));   // behind
  EXPECT_FALSE(facesAwayFromEye(p0, p1, p2, {10, 3, 0}));      // edge-on: kept
  // 1e-11 (relative) behind the plane: within the margin, kept; 1e-8: left out.
  EXPECT_FALSE(facesAwayFromEye(p0, p1, p2, {10, 0, -1e-10}));
  EXPECT_TRUE(facesAwayFromEye(p0, p1, p2, {10, 0, -1e-7}));
  // A zero-area triangle (g = 0) is kept wherever the eye is.
  EXPECT_FALSE(facesAwayFromEye(p0, p1, {2, 0, 0}, {0.2, 0.2, -5}));
}

// Why leaving them out is safe: every ray from the eye meets a left-out
// triangle from behind (g . d > 0, the same sign for the whole triangle),
// and the mesh's back faces are never a first hit (condition 1), so no
// camera ray's first hit is among them; and the kept ones are all the rest.
TEST(FrontFaces, BvhTrianglesOfASphereAreTheOnesRaysCanMeetFromTheFront) {
  UvSphere s;
  s.center = {0.5, -0.25, 0}, s.radius = 1.5;
  const TriangleMesh m = tessellate(s);
  const glm::dvec3 eye{0.3, 0.8, 4.2};
  ASSERT_TRUE(backFacesNeverFirstHit(s, m, eye));
  const std::vector<uint32_t> kept = trianglesNotFacingAway(m, eye);
  size_t k = 0, left_out = 0;
  for (uint32_t t = 0; t < m.triangles.size(); ++t) {
    const glm::dvec3 a = m.positions[m.triangles[t][0]], b = m.positions[m.triangles[t][1]],
                     c = m.positions[m.triangles[t][2]];
    const glm::dvec3 g = glm::cross(b - a, c - a);
    const bool is_kept = k < kept.size() && kept[k] == t;  // ascending
    if (is_kept) {
      ++k;
      continue;
    }
    ++left_out;
    // Rays from the eye through the centroid and near each vertex.
    for (glm::dvec3 q : {(a + b + c) / 3.0, 0.9 * a + 0.05 * (b + c), 0.9 * b + 0.05 * (a + c),
                         0.9 * c + 0.05 * (a + b)})
      EXPECT_GT(glm::dot(g, glm::normalize(q - eye)), 0.0) << "triangle " << t;
  }
  EXPECT_EQ(k, kept.size());  // every kept index named a triangle, in order
  // From 4.2 away the eye sees about a third of the sphere: about two
  // thirds of the 64 x 62 triangles face away.
  EXPECT_GT(left_out, 2400u);
  EXPECT_LT(left_out, 3200u);
  EXPECT_EQ(kept.size() + left_out, m.triangles.size());
}
