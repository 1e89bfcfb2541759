// The triangle-edge diagnostic (camera/triangle_edge.h): the distance in
// pixels, in the image plane, of a hit from the nearest edge of its
// triangle; the renderer's per-pixel channel (the smallest over the
// pixel's samples); and the pixel class it gives (image/pixel_classes.h).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <unistd.h>

#include "camera/triangle_edge.h"
#include "head_on_camera.h"
#include "golden/golden_set.h"
#include "image/compare.h"
#include "image/image.h"
#include "image/pixel_classes.h"
#include "render/renderer.h"

namespace xval {
namespace {

using testing::headOn;  // tests/unit/head_on_camera.h

TEST(TriangleEdge, DistanceInPixelsOfTheNearestEdgeInTheImagePlane) {
  const CameraRays cam(headOn());
  const double px_per_unit = testing::headOnPixelsPerUnit();
  // The edge P0 P1 lies on y = -1; P2 is 2 above it, so barycentric b2 is
  // the distance from that edge over 2.
  const glm::dvec3 P[3] = {{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
  for (double d : {1e-8, 1e-5, 1e-2}) {
    const double b2 = d / 2.0, b1 = 0.5 * (1.0 - b2);  // on the median: far from the other edges
    EXPECT_NEAR(triangleEdgePixels(cam, P, b1, b2), d * px_per_unit, 1e-9 * px_per_unit) << d;
  }
  // The centroid: each edge's distance is b_k = 1/3 times the height from
  // vertex k (2 area / |edge|): 2 for P2, 4 / sqrt(5) for P0 and P1.
  const double h_slanted = 4.0 / std::sqrt(5.0);
  EXPECT_NEAR(triangleEdgePixels(cam, P, 1.0 / 3, 1.0 / 3), std::min(2.0, h_slanted) / 3 * px_per_unit, 1e-9);
  // Tilted away from the camera by 1 radian about its edge on the x axis,
  // the same world distance from that edge is foreshortened by cos 1.
  const double c = std::cos(1.0), s = std::sin(1.0);  // tilt by 1 radian about the x axis
  const glm::dvec3 T[3] = {{-1, 0, 0}, {1, 0, 0}, {0, 2 * c, -2 * s}};
  const double d = 1e-4;
  const double at_edge = triangleEdgePixels(cam, T, 0.5 * (1 - d / 2), d / 2);
  EXPECT_LT(at_edge, d * px_per_unit);
  EXPECT_GT(at_edge, 0.5 * c * d * px_per_unit);
}

TEST(TriangleEdge, AHitBehindTheCameraOrADegenerateTriangleIsFar) {
  const CameraRays cam(headOn());
  const glm::dvec3 behind[3] = {{-1, -1, 6}, {1, -1, 6}, {0, 1, 6}};
  EXPECT_EQ(triangleEdgePixels(cam, behind, 0.3, 0.3), double(kFarFromTriangleEdge));
  const glm::dvec3 point[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  EXPECT_EQ(triangleEdgePixels(cam, point, 0.3, 0.3), double(kFarFromTriangleEdge));
}

// A head-on square of two triangles whose shared diagonal runs exactly
// through the pixel centres (i + 0.5, i + 0.5) of a square image (the
// plane's tessellation: geometry/shapes.cpp).
Scene diagonalPlane() {
  Scene s;
  s.camera.width = s.camera.height = 64;
  s.objects = {Plane{}};
  s.material.model = Lambert{glm::dvec3(1.0)};
  s.material.base_color = {0.5, 0.25, 0.125};
  s.lights = {DirectionalLight{{0, 0, -1}, glm::dvec3(1.0)}};
  return s;
}

TEST(TriangleEdge, TheRenderersChannelIsTheNearestSampleOfThePixel) {
  for (Precision prec : {Precision::Double, Precision::Float}) {
    for (int spp : {1, 4}) {
      RenderOptions o;
      o.precision = prec, o.spp = spp, o.diagnostics = true;
      const Image img = renderScene(diagonalPlane(), o);
      ASSERT_EQ(img.triangle_edge.size(), 64u * 64u);
      auto at = [&](int i, int j) { return img.triangle_edge[size_t(j) * 64 + i]; };
      for (int i = 24; i < 40; ++i) {
        // On the diagonal: the pixel centre (1 spp) or two of the 2 x 2
        // samples (at offsets 0.25 and 0.75) lie on the shared edge.
        EXPECT_LT(at(i, i), 1e-4f) << i << " spp " << spp;
        // One row below: 1 / sqrt(2) from the diagonal at the centre; with
        // 2 x 2 samples the nearest, (i + 0.75, i + 1.25), is 0.5 / sqrt(2).
        EXPECT_NEAR(at(i, i + 1), (spp == 1 ? 1.0 : 0.5) / std::sqrt(2.0), 1e-4) << i << " spp " << spp;
      }
      EXPECT_EQ(at(0, 0), kFarFromTriangleEdge);  // no sample hits
    }
  }
}

// A single wrong pixel on the shared edge is explained (its one sample is
// an edge sample: edge_fraction 1); the same error one pixel off it fails
// the comparison, whatever the fraction.
TEST(TriangleEdge, AWrongPixelOnAnEdgeIsClassifiedOneAwayFromItFails) {
  RenderOptions o;
  o.diagnostics = true;
  const Image ref = renderScene(diagonalPlane(), o);
  Tolerance t;
  t.max_abs = 2.0 / 65535, t.fraction = 0.999, t.max_unexplained = 128.0 / 65535;
  Image other = ref;
  other.pixel(30, 30)[0] = 1.0f;
  CompareMetrics m = compareImages(ref, other, t);
  EXPECT_EQ(m.overCount(PixelClass::Edge), 1);
  EXPECT_EQ(m.over_unexplained(), 0);
  EXPECT_TRUE(t.passes(m));
  other.pixel(30, 32)[0] = 1.0f;  // sqrt(2) px from the edge, far from the square's sides
  m = compareImages(ref, other, t);
  EXPECT_EQ(m.over_unexplained(), 1);
  EXPECT_EQ(m.worst_unexplained_x, 30);
  EXPECT_EQ(m.worst_unexplained_y, 32);
  EXPECT_FALSE(t.passes(m));
}

// A golden image (golden/golden_set.h) keeps texel_edge and triangle_edge
// as 16-bit floats where they are near their bound: read back, every pixel
// is on the same side of both bounds as in the render (values just above a
// bound included), so a golden comparison classifies like a live one.
TEST(TriangleEdge, AGoldenImageKeepsTheClassOfEveryPixel) {
  RenderOptions o;
  o.diagnostics = true, o.spp = 4;
  Image img = renderScene(diagonalPlane(), o);
  // Values on both sides of the bounds, and just above them (what 16-bit
  // rounding would bring onto the bound if stored as they are).
  const float just_above = 1.0f + 1.0f / 4096.0f;
  img.triangle_edge[size_t(20) * 64 + 30] = kTriangleEdgePixels * just_above;
  img.triangle_edge[size_t(21) * 64 + 30] = kTriangleEdgePixels;
  img.texel_edge[size_t(22) * 64 + 30] = kTexelEdgeRoundings * just_above;
  img.texel_edge[size_t(23) * 64 + 30] = kTexelEdgeRoundings;
  img.texel_edge[size_t(24) * 64 + 30] = 3.0f;
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("xval_golden_edges_" + std::to_string(getpid()) + ".exr");
  golden::writeGoldenImage(img, file);
  const Image back = readImage(file);
  std::filesystem::remove(file);
  ASSERT_EQ(back.triangle_edge.size(), img.triangle_edge.size());
  ASSERT_EQ(back.texel_edge.size(), img.texel_edge.size());
  int near_edge = 0;
  for (size_t i = 0; i < img.triangle_edge.size(); ++i) {
    EXPECT_EQ(back.triangle_edge[i] <= kTriangleEdgePixels, img.triangle_edge[i] <= kTriangleEdgePixels) << i;
    EXPECT_EQ(back.texel_edge[i] <= kTexelEdgeRoundings, img.texel_edge[i] <= kTexelEdgeRoundings) << i;
    near_edge += back.triangle_edge[i] <= kTriangleEdgePixels;
    if (img.triangle_edge[i] <= kTriangleEdgePixels)
      EXPECT_NEAR(back.triangle_edge[i], img.triangle_edge[i], std::ldexp(img.triangle_edge[i], -11) + 1e-7f) << i;
    for (int c = 0; c < 4; ++c) EXPECT_EQ(back.rgba[i * 4 + c], img.rgba[i * 4 + c]) << i;
  }
  EXPECT_GT(near_edge, 20);  // the diagonal
}

}  // namespace
}  // namespace xval
