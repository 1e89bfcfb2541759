// The precision probes (render/precision_probe.h) and their channels
// (image/image.h kProbeChannels): an unperturbed probe is the sample's
// colour, each channel measures what its rounding changes on scenes whose
// answer is known, and the channels survive an EXR and a golden image.
#include <gtest/gtest.h>

#include <fstream>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <unistd.h>

#include "golden/golden_set.h"
#include "head_on_camera.h"
#include "image/image.h"
#include "image/pixel_classes.h"
#include "render/precision_probe.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"

namespace xval {
namespace {

namespace fs = std::filesystem;

// tests/unit/head_on_camera.h: world x maps to image x = 50 + kPixelsPerUnit x.
using testing::headOn;
const double kPixelsPerUnit = testing::headOnPixelsPerUnit();

// A 2 x 2 square facing the camera whose left edge is at image x = left,
// lit head-on (Lambert: every hit is its base colour).
Scene squareWithLeftEdgeAt(double left) {
  Scene s;
  s.camera = headOn();
  Plane p;
  p.center = {(left - 50.0) / kPixelsPerUnit + 1.0, 0, 0};
  s.objects = {p};
  s.material.model = Lambert{glm::dvec3(1.0)};
  s.material.base_color = {0.5, 0.25, 0.125};
  s.lights = {DirectionalLight{{0, 0, -1}, glm::dvec3(1.0)}};
  return s;
}

Image render(const Scene& s, int spp, Precision prec = Precision::Double) {
  RenderOptions o;
  o.spp = spp, o.precision = prec, o.diagnostics = true;
  return renderScene(s, o);
}

float at(const std::vector<float>& v, int i, int j) { return v[size_t(j) * 100 + i]; }

// barycentricDerivatives is the derivative of planeBarycentrics: on a
// tilted triangle, central differences over 1e-4 px agree to 1e-6 of it.
TEST(PrecisionProbe, BarycentricDerivativesAreThoseOfThePlaneIntersection) {
  const CameraRays cam(headOn());
  const glm::dvec3 P[3] = {{-1, -0.5, 0.3}, {1.2, -0.7, -0.8}, {0.1, 1.1, 0.2}};
  const double x = 47.3, y = 55.8, h = 1e-4;
  const glm::dvec2 b = planeBarycentrics(cam, P, x, y);
  const BarycentricDerivatives d = barycentricDerivatives(cam, P, b.x, b.y, 1.0);
  const glm::dvec2 fx = (planeBarycentrics(cam, P, x + h, y) - planeBarycentrics(cam, P, x - h, y)) / (2 * h);
  const glm::dvec2 fy = (planeBarycentrics(cam, P, x, y + h) - planeBarycentrics(cam, P, x, y - h)) / (2 * h);
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(d.dx[k], fx[k], 1e-6 * glm::length(fx)) << k;
    EXPECT_NEAR(d.dy[k], fy[k], 1e-6 * glm::length(fy)) << k;
  }
}

// On a head-on triangle with uv = world (x, y), uv is affine in the image:
// the 2x2-quad differences are the exact derivatives, 1 / kPixelsPerUnit
// per pixel along u and -1 / kPixelsPerUnit along v (image y runs down),
// per sample step 1 / n, whichever corner of its quad the sample is in.
TEST(PrecisionProbe, QuadDifferencesOfAnAffineUvAreItsDerivatives) {
  const CameraRays cam(headOn());
  const glm::dvec3 P[3] = {{-2, -2, 0}, {2, -2, 0}, {0, 2, 0}};
  const glm::dvec2 uv[3] = {{-2, -2}, {2, -2}, {0, 2}};
  for (int n : {1, 2, 4})
    for (double x : {50.1, 50.6, 51.3, 51.9})
      for (double y : {49.2, 49.7}) {
        const double s = 1.0 / (kPixelsPerUnit * n);
        for (const auto& q : quadUvDerivativeChoices(cam, P, uv, x, y, n)) {
          EXPECT_NEAR(q[0].x, s, 1e-9) << n << " " << x << " " << y;
          EXPECT_NEAR(q[0].y, 0.0, 1e-9);
          EXPECT_NEAR(q[1].x, 0.0, 1e-9);
          EXPECT_NEAR(q[1].y, -s, 1e-9) << n << " " << x << " " << y;
        }
      }
}

TEST(PrecisionProbe, AnUnperturbedProbeIsTheSampleColourBitForBit) {
  Scene s = loadScene(std::string(XVAL_REFERENCE_DIR) + "/scenes/fig1_yiq_front.json");
  s.camera.width = s.camera.height = 48;
  for (Precision prec : {Precision::Double, Precision::Float}) {
    const PreparedScene prepared(s, prec);
    RenderOptions o;
    o.spp = 1, o.precision = prec, o.rasterise = false;
    Image img(48, 48, true);
    prepared.render(o, img);
    int hits = 0;
    for (int j = 0; j < 48; ++j)
      for (int i = 0; i < 48; ++i) {
        const PreparedScene::ProbeCheck c = prepared.checkProbe(i + 0.5, j + 0.5, 1);
        if (!c.hit) continue;
        ++hits;
        for (int q = 0; q < 3; ++q) {
          EXPECT_EQ(std::memcmp(&c.colour[q], &c.unperturbed[q], sizeof(double)), 0) << i << "," << j;
          if (prec == Precision::Double) EXPECT_EQ(float(c.unperturbed[q]), img.pixel(i, j)[q]) << i << "," << j;
        }
      }
    EXPECT_GT(hits, 200);
  }
}

// The left edge 0.003 px right of the samples at x = 40.25 (2 x 2 samples
// per pixel: offsets 0.25, 0.75): those two samples of pixel 40 miss,
// within 2^-8 px of the edge of the triangle the pixel's other samples
// hit: 2 / 4. Pixels 39 and 41: no sample within 2^-8 px of any edge.
// BoundaryNearness decides segmentDistance(p, a, b) <= within without the
// square root and the clamp's division: the same answer for every point,
// including a squared distance just above within^2 whose square root still
// rounds to within (2^-16 (1 + 2^-52) for within = 2^-8), points beyond
// either end, degenerate and non-finite segments.
TEST(PrecisionProbe, BoundaryNearnessIsSegmentDistanceWithin) {
  const double w = kTriangleEdgePixels;
  const BoundaryNearness near(w);
  auto check = [&](glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
    EXPECT_EQ(near.segment(p, a, b), segmentDistance(p, a, b) <= w)
        << "p " << p.x << " " << p.y << " a " << a.x << " " << a.y << " b " << b.x << " " << b.y;
  };
  // Past the end (0, 0) of the segment (-1, 0)-(0, 0): q = (2^-34, 2^-8).
  const glm::dvec2 edge_p(std::ldexp(1.0, -34), std::ldexp(1.0, -8));
  ASSERT_EQ(glm::dot(edge_p, edge_p), std::ldexp(1.0, -16) * (1.0 + std::ldexp(1.0, -52)));
  check(edge_p, {-1, 0}, {0, 0});
  EXPECT_TRUE(near.segment(edge_p, {-1, 0}, {0, 0}));
  // Around the distance w from segments of every direction and length, along them and past their ends.
  uint64_t state = 12345;
  auto uniform = [&]() {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) * 0x1p-53;
  };
  for (int k = 0; k < 200000; ++k) {
    const glm::dvec2 a(1000.0 * uniform() - 500.0, 1000.0 * uniform() - 500.0);
    const double len = k % 7 == 0 ? 0.0 : std::ldexp(uniform(), -int(uniform() * 12)) * 4.0;
    const double ang = 6.283185307179586 * uniform();
    const glm::dvec2 dir(std::cos(ang), std::sin(ang)), b = a + len * dir;
    const double along = 1.5 * uniform() - 0.25, off = w * (1.0 + (uniform() - 0.5) * std::ldexp(1.0, -int(uniform() * 50)));
    const glm::dvec2 p = a + along * (b - a) + off * glm::dvec2(-dir.y, dir.x);
    check(p, a, b);
    check(a + off * dir * (uniform() < 0.5 ? -1.0 : 1.0), a, b);
  }
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (const glm::dvec2 p : {glm::dvec2(0, 0), glm::dvec2(nan, 0), glm::dvec2(inf, 0), glm::dvec2(1e300, 1e300)})
    for (const glm::dvec2 b : {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(inf, 0), glm::dvec2(nan, 1), glm::dvec2(1e200, -1e200)})
      check(p, {0, 0}, b), check(p, {-1e200, 0}, b);
}

TEST(PrecisionProbe, EdgeFractionCountsTheSamplesNearAnEdgeOfAHitTriangle) {
  const Image img = render(squareWithLeftEdgeAt(40.253), 4);
  ASSERT_EQ(img.edge_fraction.size(), 100u * 100u);
  for (int j = 45; j < 55; ++j) {  // far from the square's diagonal, top and bottom
    EXPECT_EQ(at(img.edge_fraction, 40, j), 0.5f) << j;
    EXPECT_EQ(at(img.edge_fraction, 39, j), 0.0f) << j;
    EXPECT_EQ(at(img.edge_fraction, 41, j), 0.0f) << j;
  }
}

// The edge 0.003 px right of x = 39.75: pixel 39's samples all miss, and
// its two at x = 39.75 lie within 2^-8 px of the triangle its neighbour 40
// hit: 2 / 4, with no hit of its own. Pixel 40 (nearest sample 0.497 px
// away) and 38: 0.
TEST(PrecisionProbe, AMissedPixelCountsItsSamplesNearANeighboursTriangle) {
  const Image img = render(squareWithLeftEdgeAt(39.753), 4);
  for (int j = 45; j < 55; ++j) {
    EXPECT_EQ(img.pixel(39, j)[3], 0.0f) << j;
    EXPECT_EQ(at(img.edge_fraction, 39, j), 0.5f) << j;
    EXPECT_EQ(at(img.edge_fraction, 40, j), 0.0f) << j;
    EXPECT_EQ(at(img.edge_fraction, 38, j), 0.0f) << j;
  }
}

// A sliver no sample hits: a triangle 0.001 px thin whose lower edge
// passes 0.002 px above the sample row y = 50.5 from x = 30 to 70. Nothing
// in the image is hit, yet a rasteriser's 2^-8 px may give it those
// samples: every pixel of row 50 between is an edge sample. (Found only by
// binning the triangles over the pixels not covered whole: no neighbour
// hits it.)
TEST(PrecisionProbe, ASliverNoSampleHitsStillMakesEdgeSamples) {
  const fs::path dir = fs::temp_directory_path() / ("xval_sliver_" + std::to_string(getpid()));
  fs::create_directories(dir);
  auto world = [](double ix, double iy) { return glm::dvec2((ix - 50.0) / kPixelsPerUnit, (50.0 - iy) / kPixelsPerUnit); };
  const glm::dvec2 a = world(30.0, 50.498), b = world(70.0, 50.498), c = world(70.0, 50.497);
  {
    std::ofstream obj(dir / "sliver.obj");
    obj.precision(17);
    obj << "v " << a.x << " " << a.y << " 0\nv " << b.x << " " << b.y << " 0\nv " << c.x << " " << c.y
        << " 0\nvn 0 0 1\nf 1//1 2//1 3//1\n";
    std::ofstream scene(dir / "sliver.json");
    scene << R"({"format": "xval-scene/1", "name": "sliver",
      "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 60, "width": 100, "height": 100},
      "objects": [{"shape": "mesh", "path": "sliver.obj"}],
      "material": {"model": {"type": "lambert"}}, "lights": [{"type": "directional", "direction": [0, 0, -1]}]})";
  }
  const Image img = render(loadScene(dir / "sliver.json"), 1);
  fs::remove_all(dir);
  for (int i = 31; i < 69; ++i) {
    EXPECT_EQ(img.pixel(i, 50)[3], 0.0f) << i;  // no sample hits it
    EXPECT_EQ(at(img.edge_fraction, i, 50), 1.0f) << i;
    EXPECT_EQ(at(img.edge_fraction, i, 49), 0.0f) << i;
    EXPECT_EQ(at(img.edge_fraction, i, 51), 0.0f) << i;
  }
  EXPECT_EQ(at(img.edge_fraction, 20, 50), 0.0f);
}

// The shared diagonal of a 64 x 64 head-on plane passes through the pixel
// centres (i + 0.5, i + 0.5) (tests/unit/triangle_edge_test.cpp): at 1 spp
// those pixels are near an edge of their own triangle, the ones beside
// them (1/sqrt(2) px away) are not.
TEST(PrecisionProbe, EdgeFractionCountsAnEdgeSharedInsideAMesh) {
  Scene s;
  s.camera.width = s.camera.height = 64;
  s.objects = {Plane{}};
  s.material.model = Lambert{glm::dvec3(1.0)};
  s.lights = {DirectionalLight{{0, 0, -1}, glm::dvec3(1.0)}};
  const Image img = render(s, 1);
  for (int i = 24; i < 40; ++i) {
    EXPECT_EQ(img.edge_fraction[size_t(i) * 64 + i], 1.0f) << i;
    EXPECT_EQ(img.edge_fraction[size_t(i + 1) * 64 + i], 0.0f) << i;
  }
}

// A texture whose codes rise by one per column (k / 255 at column k): a
// bilinear lookup is linear in u, and on a head-on square u is linear in
// image x, so the colour's slope is (1/255 per texel) (256 texels per u)
// / (2 kPixelsPerUnit pixels per u) and a 2^-8 px move changes it by that
// times 2^-8; along y it does not change.
fs::path writeRamp() {
  const fs::path file = fs::temp_directory_path() / ("xval_ramp_" + std::to_string(getpid()) + ".png");
  std::vector<unsigned char> px(256 * 4 * 3);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 256; ++x)
      for (int c = 0; c < 3; ++c) px[(size_t(y) * 256 + x) * 3 + c] = (unsigned char)x;
  auto out = OIIO::ImageOutput::create(file.string());
  EXPECT_TRUE(out);
  OIIO::ImageSpec spec(256, 4, 3, OIIO::TypeDesc::UINT8);
  EXPECT_TRUE(out->open(file.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data()) && out->close());
  return file;
}

TEST(PrecisionProbe, PositionProbeIsTheColourSlopeTimesTheStep) {
  const fs::path ramp = writeRamp();
  Scene s = squareWithLeftEdgeAt(50.0 - kPixelsPerUnit);  // centred
  s.material.texture = TextureSpec{TextureSpec::Source::Image, ramp, TextureFilter::Bilinear, nullptr};
  for (Precision prec : {Precision::Double, Precision::Float}) {
    const Image img = render(s, 1, prec);
    const double expected = 256.0 / 255.0 / (2.0 * kPixelsPerUnit) * kPositionStepPixels;
    for (int j = 40; j < 60; j += 3)
      for (int i = 40; i < 60; i += 3)
        EXPECT_NEAR(at(img.precision_position, i, j), expected, 2e-3 * expected) << i << "," << j;
    // The uv probe: 1/256 texel of a 1/255-per-texel ramp.
    EXPECT_NEAR(at(img.precision_uv, 50, 50), kUvStepTexels / 255.0, 2e-3 / 255.0 * kUvStepTexels);
  }
  fs::remove(ramp);
}

// Ambient light only: the colour does not depend on N, so turning it
// changes nothing; a tight highlight (shininess 1000, the light behind the
// eye) changes under a 2^-9 rad turn.
TEST(PrecisionProbe, NormalProbeIsZeroWithoutLightAndPositiveInAHighlight) {
  Scene s = squareWithLeftEdgeAt(50.0 - kPixelsPerUnit);
  s.shading = ShadingMode::Phong;
  s.lights = {AmbientLight{glm::dvec3(0.5)}};
  Image img = render(s, 4);
  float largest = 0.0f;
  for (float v : img.precision_normal) largest = std::max(largest, v);
  EXPECT_EQ(largest, 0.0f);
  ClassicPhong phong;
  phong.ka = 0.0, phong.kd = 0.0, phong.ks = 1.0, phong.shininess = 1000.0;
  s.material.model = phong;
  s.lights = {PointLight{{0, 0, 5}, glm::dvec3(1.0), {}}};
  img = render(s, 4);
  for (float v : img.precision_normal) largest = std::max(largest, v);
  EXPECT_GT(largest, 1e-3f);
}

// Two squares: the left faces the camera, the right faces away (its
// shading normal is backfacing; lit from the camera's side it is black,
// turned around it is its base colour). backfacing_flip is the base
// colour's largest channel over the right square and 0 wherever no
// sample is backfacing.
TEST(PrecisionProbe, BackfacingFlipIsPositiveOnlyWhereASampleIsBackfacing) {
  Scene s = squareWithLeftEdgeAt(10.0);
  Plane away;
  away.center = {(60.0 - 50.0) / kPixelsPerUnit + 1.0, 0, 0};
  away.normal = {0, 0, -1};
  s.objects.push_back(away);
  const Image img = render(s, 4);
  int flipped = 0;
  for (size_t k = 0; k < img.backfacing.size(); ++k) {
    if (img.backfacing[k] == 0.0f) EXPECT_EQ(img.backfacing_flip[k], 0.0f) << k;
    if (img.backfacing[k] == 1.0f && img.rgba[k * 4 + 3] == 1.0f) {
      EXPECT_EQ(img.backfacing_flip[k], 0.5f) << k;
      ++flipped;
    }
  }
  EXPECT_GT(flipped, 500);
}

// The channels survive an EXR (bit for bit) and a golden image (16-bit
// floats: relative error <= 2^-11).
TEST(PrecisionProbe, TheChannelsSurviveAnExrAndAGoldenImage) {
  Image a(9, 7, true);
  uint32_t state = 7;
  for (const DiagnosticsChannel& c : kProbeChannels)
    for (float& f : a.*c.member) f = float((state = state * 1664525u + 1013904223u) >> 8) / float(1 << 24);
  const fs::path exr = fs::temp_directory_path() / ("xval_probes_" + std::to_string(getpid()) + ".exr");
  const fs::path gold = fs::temp_directory_path() / ("xval_probes_golden_" + std::to_string(getpid()) + ".exr");
  writeImage(a, exr);
  golden::writeGoldenImage(a, gold);
  const Image b = readImage(exr), g = readImage(gold);
  fs::remove(exr), fs::remove(gold);
  for (const DiagnosticsChannel& c : kProbeChannels) {
    ASSERT_EQ((b.*c.member).size(), (a.*c.member).size()) << c.name;
    ASSERT_EQ((g.*c.member).size(), (a.*c.member).size()) << c.name;
    EXPECT_EQ(std::memcmp((b.*c.member).data(), (a.*c.member).data(), (a.*c.member).size() * sizeof(float)), 0)
        << c.name;
    for (size_t k = 0; k < (a.*c.member).size(); ++k)
      EXPECT_NEAR((g.*c.member)[k], (a.*c.member)[k], std::ldexp((a.*c.member)[k], -11) + 6e-8f) << c.name;
  }
  // copyDiagnostics hands them on.
  Image other(9, 7, false);
  copyDiagnostics(b, other);
  for (const DiagnosticsChannel& c : kProbeChannels) EXPECT_EQ(other.*c.member, b.*c.member) << c.name;
}

}  // namespace
}  // namespace xval
