// The renderer end to end on scenes whose image is known analytically, and
// the BVH against brute force.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstring>
#include <optional>

#include <random>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "render/accel.h"
#include "render/ray_triangle.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"

using namespace xval;

namespace {

Scene litPlane(ShadingMode mode) {
  Scene s;
  s.camera.width = 32, s.camera.height = 24;
  Plane p;
  s.objects = {p};
  s.material.model = Lambert{glm::dvec3(1.0)};
  s.material.base_color = {0.5, 0.25, 0.125};
  s.lights = {DirectionalLight{{0, 0, -1}, glm::dvec3(1.0)}};
  s.shading = mode;
  return s;
}

}  // namespace

// A plane facing the camera, lit head-on by a directional Lambert light:
// every covered pixel is exactly the base colour, in every shading mode
// and precision; pixels off the plane are 0 with alpha 0.
TEST(Renderer, HeadOnLambertPlaneIsExactlyTheBaseColour) {
  for (ShadingMode mode : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    for (Precision prec : {Precision::Double, Precision::Float}) {
      Scene s = litPlane(mode);
      RenderOptions o;
      o.precision = prec;
      Image img = renderScene(s, o);
      const float* centre = img.pixel(16, 12);
      EXPECT_EQ(centre[0], 0.5f);
      EXPECT_EQ(centre[1], 0.25f);
      EXPECT_EQ(centre[2], 0.125f);
      EXPECT_EQ(centre[3], 1.0f);
      const float* corner = img.pixel(0, 0);  // the plane spans +-1, the view +-1.74
      EXPECT_EQ(corner[3], 0.0f);
      EXPECT_EQ(corner[0], 0.0f);
    }
  }
}

// Lambert on a finely tessellated sphere with Phong shading: each pixel
// equals max(N.L, 0) of the exact sphere normal at the hit, up to the
// tessellation error. With dtheta = pi/128 between rings the chord sags by
// r (1 - cos(dtheta/2)) = 7.5e-5 inside the sphere; the hit moves by up to
// sag / cos(i) along the ray, turning the normal by sag tan(i) <= 1.3e-4
// for cos(i) >= 0.5; interpolating unit normals across a facet adds at most
// dtheta^2 / 8 = 7.5e-5. The bound below is their sum, rounded up.
TEST(Renderer, SphereLambertMatchesAnalyticNormal) {
  Scene s;
  s.camera.width = s.camera.height = 64;
  UvSphere sph;
  sph.segments_longitude = 256, sph.segments_latitude = 128;
  s.objects = {sph};
  s.material.model = Lambert{glm::dvec3(1.0)};
  glm::dvec3 dir = glm::normalize(glm::dvec3(-1, -1, -1));
  s.lights = {DirectionalLight{dir, glm::dvec3(1.0)}};
  Image img = renderScene(s, RenderOptions{});
  CameraRays cam(s.camera);
  double worst = 0;
  int covered = 0;
  for (int j = 0; j < 64; ++j) {
    for (int i = 0; i < 64; ++i) {
      glm::dvec3 d = cam.direction(i + 0.5, j + 0.5), o = cam.origin;
      // Exact sphere hit.
      double b = glm::dot(o, d), c = glm::dot(o, o) - 1.0, disc = b * b - c;
      if (disc < 0.0 || img.pixel(i, j)[3] == 0.0f) continue;
      glm::dvec3 n = glm::normalize(o + (-b - std::sqrt(disc)) * d);
      if (glm::dot(n, -d) < 0.5) continue;  // cos(i) >= 0.5 only
      double expect = std::max(0.0, glm::dot(n, -dir));
      worst = std::max(worst, std::abs(img.pixel(i, j)[0] - expect));
      ++covered;
    }
  }
  EXPECT_GT(covered, 700);  // the disc is ~1120 px, 3/4 of it has cos(i) >= 0.5
  EXPECT_LT(worst, 2.1e-4);
}

// Embree's traversal with the double-precision callback finds exactly the
// closest hit that brute force over all triangles finds.
TEST(Renderer, DoubleAccelMatchesBruteForce) {
  TorusKnot k;
  k.segments_along = 96, k.segments_around = 12;
  std::vector<TriangleMesh> meshes{tessellateTorusKnot(k)};
  Accel accel(meshes, Precision::Double);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int hits = 0;
  for (int i = 0; i < 3000; ++i) {
    glm::dvec3 o(u(rng) * 0.5, u(rng) * 0.5, 4.0);
    glm::dvec3 d = glm::normalize(glm::dvec3(u(rng) * 1.5, u(rng) * 1.5, 0) - o);
    Hit h = accel.intersect(o, d);
    RayShear r(o, d);
    double best = 1e300;
    uint32_t best_tri = 0;
    for (uint32_t t = 0; t < meshes[0].triangles.size(); ++t) {
      const auto& tri = meshes[0].triangles[t];
      TriangleHit th;
      if (intersectTriangle(r, meshes[0].positions[tri[0]], meshes[0].positions[tri[1]],
                            meshes[0].positions[tri[2]], 0.0, best, th))
        best = th.t, best_tri = t;
    }
    ASSERT_EQ(h.hit, best < 1e300) << i;
    if (h.hit) {
      ++hits;
      EXPECT_EQ(h.t, best);
      EXPECT_EQ(h.triangle, best_tri);
    }
  }
  EXPECT_GT(hits, 500);
}

// The float path agrees with the double path away from silhouettes.
TEST(Renderer, FloatAgreesWithDoubleOnThePaperKnot) {
  Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/fig1_yiq_front.json");
  s.camera.width = s.camera.height = 128;
  RenderOptions od, of;
  of.precision = Precision::Float;
  Image a = renderScene(s, od), b = renderScene(s, of);
  int mask_diff = 0, covered = 0;
  std::vector<float> errs;
  for (size_t i = 0; i < size_t(128 * 128); ++i) {
    bool ha = a.rgba[i * 4 + 3] > 0, hb = b.rgba[i * 4 + 3] > 0;
    if (ha != hb) { ++mask_diff; continue; }
    if (!ha) continue;
    ++covered;
    for (int c = 0; c < 3; ++c) errs.push_back(std::abs(a.rgba[i * 4 + c] - b.rgba[i * 4 + c]));
  }
  std::sort(errs.begin(), errs.end());
  EXPECT_GT(covered, 3000);
  EXPECT_LT(mask_diff, 10);
  EXPECT_LT(errs[size_t(errs.size() * 0.999)], 2e-3);
}

// With n x n samples, a silhouette pixel gets fractional alpha, and an
// interior pixel of constant colour keeps its exact value.
TEST(Renderer, StratifiedSamplesGiveFractionalCoverage) {
  Scene s = litPlane(ShadingMode::Phong);
  // Half-width 0.95 puts the plane's edges at x = 16 +- 6.553 px: 2 of the
  // 4 sample columns of pixels 22 and 9 are covered.
  std::get<Plane>(s.objects[0].shape).size = {1.9, 1.9};
  RenderOptions o;
  o.spp = 16;
  Image img = renderScene(s, o);
  EXPECT_EQ(img.pixel(16, 12)[0], 0.5f);
  EXPECT_EQ(img.pixel(16, 12)[3], 1.0f);
  int partial = 0;
  for (int i = 0; i < 32; ++i) {
    float a = img.pixel(i, 12)[3];
    if (a > 0.0f && a < 1.0f) {
      ++partial;
      EXPECT_NEAR(img.pixel(i, 12)[0], 0.5f * a, 1e-6);  // premultiplied
    }
  }
  EXPECT_EQ(partial, 2);  // the plane's left and right edges
  EXPECT_EQ(img.pixel(22, 12)[3], 0.5f);
  EXPECT_EQ(img.pixel(9, 12)[3], 0.5f);
}

// The fast path's rasterised visibility is watertight: a head-on square of
// two triangles whose shared diagonal runs exactly through the pixel centres
// (i + 0.5, i + 0.5) of a square image; every pixel the double-precision
// ray path covers, the raster covers too, with no hole on the diagonal.
TEST(Renderer, RasterisedVisibilityIsWatertightOnASharedEdge) {
  Scene s = litPlane(ShadingMode::Phong);
  s.camera.width = s.camera.height = 64;
  RenderOptions od, of;
  of.precision = Precision::Float;
  RenderStats stats;
  Image a = renderScene(s, od), b = renderScene(s, of, &stats);
  EXPECT_STREQ(stats.visibility, "rasterised");
  int covered = 0, diagonal = 0;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      EXPECT_EQ(a.pixel(i, j)[3], b.pixel(i, j)[3]) << "pixel " << i << "," << j;
      covered += b.pixel(i, j)[3] == 1.0f;
      diagonal += i == j && b.pixel(i, j)[3] == 1.0f;
    }
  EXPECT_GT(covered, 64 * 64 / 4);
  EXPECT_GT(diagonal, 20);  // the diagonal crosses the plane's covered part
}

// The fast path (float, rasterised) agrees with the exact reference path on
// the paper's Table 2 knot within the project's default tolerance
// (reference/tolerances.json: 2/65535 on 99.9% of the pixels), with the
// same hit mask; the Embree-packet float path finds the same hit mask.
TEST(Renderer, FastPathAgreesWithTheReferenceOnTheTable2Knot) {
  Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json");
  RenderOptions od, of, ofr;
  of.precision = ofr.precision = Precision::Float;
  ofr.rasterise = false;
  RenderStats sf, sr;
  Image a = renderScene(s, od), b = renderScene(s, of, &sf), c = renderScene(s, ofr, &sr);
  EXPECT_STREQ(sf.visibility, "rasterised");
  EXPECT_STREQ(sr.visibility, "Embree 16-ray packets (float)");
  size_t covered = 0, within = 0, mask_fast = 0, mask_rays = 0;
  for (size_t i = 0; i < a.rgba.size() / 4; ++i) {
    mask_fast += (a.rgba[i * 4 + 3] > 0) != (b.rgba[i * 4 + 3] > 0);
    mask_rays += (a.rgba[i * 4 + 3] > 0) != (c.rgba[i * 4 + 3] > 0);
    if (a.rgba[i * 4 + 3] == 0) continue;
    ++covered;
    float e = 0;
    for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(a.rgba[i * 4 + k] - b.rgba[i * 4 + k]));
    within += e * 65535.0f <= 2.0f;
  }
  EXPECT_GT(covered, 200000u);
  EXPECT_EQ(mask_fast, 0u);
  EXPECT_LE(mask_rays, 10u);
  EXPECT_GE(double(within) / double(covered), 0.999);
}

// The rasteriser's SIMD loop (render/raster_band.h) and the shading kernel
// give the same image, bit for bit, on every instruction set compiled in
// that this CPU runs (final colour and every diagnostic channel, so the
// hits' barycentrics and depths too), at 1 and 4 samples per pixel.
TEST(Renderer, RasterBandIsTheSameOnEveryInstructionSet) {
  Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/table2_knot_yiq.json");
  s.camera.width = s.camera.height = 200;
  for (int spp : {1, 4})
    for (bool diagnostics : {false, true}) {
      RenderOptions o;
      o.precision = Precision::Float;
      o.spp = spp;
      o.diagnostics = diagnostics;
      const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
      ASSERT_GE(targets.size(), 2u);
      std::optional<Image> first;
      for (int64_t t : targets) {
        hwy::SetSupportedTargetsForTest(t);
        SCOPED_TRACE(std::string(hwy::TargetName(t)) + ", spp " + std::to_string(spp));
        Image img = renderScene(s, o);
        if (!first) {
          first = std::move(img);
          continue;
        }
        EXPECT_EQ(0, std::memcmp(first->rgba.data(), img.rgba.data(), img.rgba.size() * sizeof(float)));
        EXPECT_EQ(first->depth, img.depth);
        EXPECT_EQ(first->raw, img.raw);
      }
      hwy::SetSupportedTargetsForTest(0);
    }
}

// A camera inside the scene's extent (the plane reaches behind it): the
// raster is not applicable, the float path traces Embree packets and says
// so, and still matches the double path's hit mask.
TEST(Renderer, FastPathFallsBackToPacketsWhenGeometryIsBehindTheCamera) {
  Scene s = litPlane(ShadingMode::Phong);
  Plane floor;
  floor.center = {0, -1, 0}, floor.normal = {0, 1, 0}, floor.size = {40, 40};
  s.objects = {floor};
  s.lights = {DirectionalLight{{0, -1, 0}, glm::dvec3(1.0)}};
  RenderOptions od, of;
  of.precision = Precision::Float;
  RenderStats stats;
  Image a = renderScene(s, od), b = renderScene(s, of, &stats);
  EXPECT_STREQ(stats.visibility, "Embree 16-ray packets (float)");
  int diff = 0, covered = 0;
  for (size_t i = 0; i < a.rgba.size() / 4; ++i) {
    diff += (a.rgba[i * 4 + 3] > 0) != (b.rgba[i * 4 + 3] > 0);
    covered += b.rgba[i * 4 + 3] > 0;
  }
  EXPECT_GT(covered, 100);
  EXPECT_LE(diff, 2);
}

// A vertex just in front of the eye projects to ~1e14 px: the raster's
// bounding boxes are clamped in double before the conversion to int (a
// double beyond int's range converted to int is undefined behaviour, which
// UBSan reports in the sanitizer build). The float image still matches the
// double path's mask.
TEST(Renderer, RasterClampsVerticesProjectedFarOffScreen) {
  Scene s = litPlane(ShadingMode::Phong);
  s.camera.position = {0, 0, 1e-6};  // float32's grid is ~1e-13 there
  s.camera.target = {0, 0, -1};
  Plane p;
  p.center = {0, 0, 1e-6 - 1e-12};  // in front of the eye by 1e-12
  p.size = {2, 2};
  Plane back;
  back.center = {0, 0, -1};
  s.objects = {p, back};
  RenderOptions od, of;
  of.precision = Precision::Float;
  RenderStats stats;
  Image a = renderScene(s, od), b = renderScene(s, of, &stats);
  EXPECT_STREQ(stats.visibility, "rasterised");
  int diff = 0;
  for (size_t i = 0; i < a.rgba.size() / 4; ++i) diff += (a.rgba[i * 4 + 3] > 0) != (b.rgba[i * 4 + 3] > 0);
  EXPECT_LE(diff, 2);
}
