// The trilinear filter's mip chain, level of detail and blend
// (texture/mip_chain.h), and the renderer's footprint and the unnormalised
// normal (scene options normalize_normal and filter trilinear).
#include <gtest/gtest.h>

#include <cmath>

#include "render/renderer.h"
#include "scene/scene.h"
#include "texture/brick.h"
#include "texture/mip_chain.h"

using namespace xval;

namespace {

// W x H, texel (x, y) = (x, y, x + 10 y): every box mean is known.
Texture ramp(int w, int h) {
  Texture t;
  t.width = w, t.height = h;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) t.rgb.insert(t.rgb.end(), {float(x), float(y), float(x + 10 * y)});
  return t;
}

}  // namespace

TEST(MipChain, HalvesWithFloorDownToOneByOneAndBoxFilters) {
  const MipChain c = mipChain(ramp(5, 3));
  ASSERT_EQ(c.levels.size(), 3u);  // q = floor(log2(5)) = 2
  EXPECT_EQ(c.levels[1].width, 2);
  EXPECT_EQ(c.levels[1].height, 1);
  EXPECT_EQ(c.levels[2].width, 1);
  EXPECT_EQ(c.levels[2].height, 1);
  // Level 1 texel (1, 0): the mean of x in {2, 3}, y in {0, 1}; the odd
  // last column (x = 4) and row (y = 2) are left out.
  EXPECT_EQ(c.levels[1].texel(1, 0), glm::vec3(2.5f, 0.5f, 7.5f));
  EXPECT_EQ(c.levels[1].texel(0, 0), glm::vec3(0.5f, 0.5f, 5.5f));
  // Level 2 from level 1's 2 x 1: its one row counts twice.
  EXPECT_EQ(c.levels[2].texel(0, 0), glm::vec3(1.5f, 0.5f, 6.5f));
}

TEST(MipChain, LevelOfDetailIsLog2OfTheLongerFootprintClamped) {
  const MipChain c = mipChain(ramp(64, 16));  // q = 6
  // rho = max(|(64 du/dx, 16 dv/dx)|, |(64 du/dy, 16 dv/dy)|)
  EXPECT_DOUBLE_EQ(c.lambda({4.0 / 64, 0}, {0, 1.0 / 16}), 2.0);
  EXPECT_DOUBLE_EQ(c.lambda({0, 0}, {3.0 / 64, 4.0 / 16}), std::log2(5.0));
  EXPECT_DOUBLE_EQ(c.lambda({0.5 / 64, 0}, {0, 0.5 / 16}), 0.0);  // magnified
  EXPECT_DOUBLE_EQ(c.lambda({1000.0, 0}, {0, 0}), 6.0);            // clamped to q
  EXPECT_DOUBLE_EQ(c.lambda({INFINITY, 0}, {0, 0}), 6.0);
}

TEST(MipChain, BlendsTheTwoLevelsAroundLambda) {
  const MipChain c = mipChain(makeBrickTexture());
  const glm::dvec2 uv(0.3, 0.7);
  const glm::dvec3 l2 = c.levels[2].lookup(uv, TextureFilter::Bilinear);
  const glm::dvec3 l3 = c.levels[3].lookup(uv, TextureFilter::Bilinear);
  ASSERT_NE(l2, l3);
  EXPECT_EQ(c.lookup(uv, 2.0), l2);
  const glm::dvec3 mix = c.lookup(uv, 2.25);
  for (int q = 0; q < 3; ++q) EXPECT_NEAR(mix[q], 0.75 * l2[q] + 0.25 * l3[q], 1e-15);
  EXPECT_EQ(c.lookup(uv, 0.0), c.levels[0].lookup(uv, TextureFilter::Bilinear));
  EXPECT_EQ(c.lookup(uv, double(c.maxLevel())), glm::dvec3(c.levels.back().texel(0, 0)));
}

namespace {

// A head-on square plane of the brick, side 2, filling `fill` of the
// image's height: its uv per pixel is exactly 1 / (fill H), so the brick's
// rho is 512 / (fill H) texels at every pixel.
Scene headOnPlane(int size, double fill, TextureFilter f) {
  Scene s;
  s.camera.width = s.camera.height = size;
  s.camera.fov_y_deg = 90.0;  // tan = 1: the image spans [-d, d] at distance d
  s.camera.position = {0, 0, 1.0 / fill};
  s.objects = {Plane{}};
  s.material.model = Lambert{};
  s.material.texture = TextureSpec{TextureSpec::Source::Brick, {}, f, {}};
  s.lights = {AmbientLight{glm::dvec3(1.0)}};
  return s;
}

}  // namespace

// The renderer's footprint: on a head-on plane at rho = 16 texels (lambda
// 4) every pixel is level 4's bilinear lookup at its uv, on every path.
TEST(RendererTrilinear, HeadOnPlaneReadsTheLevelOfItsFootprint) {
  const int size = 64;
  const Scene s = headOnPlane(size, 0.5, TextureFilter::Trilinear);  // uv per pixel 1/32 -> rho 16: lambda 4
  const MipChain c = mipChain(makeBrickTexture());
  for (Precision p : {Precision::Double, Precision::Float}) {
    RenderOptions o;
    o.precision = p;
    const Image img = renderScene(s, o);
    double worst = 0;
    int covered = 0;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const float* px = img.pixel(i, j);
        if (px[3] == 0) continue;
        ++covered;
        // uv at the pixel centre: the plane spans pixels [16, 48) each way.
        const glm::dvec2 uv((i + 0.5 - 16) / 32.0, (j + 0.5 - 16) / 32.0);
        const glm::dvec3 want = c.lookup(uv, 4.0);
        for (int q = 0; q < 3; ++q) worst = std::max(worst, std::abs(px[q] - want[q]));
      }
    EXPECT_EQ(covered, 32 * 32) << toString(p);
    EXPECT_LT(worst, 1e-5) << toString(p);
  }
  // At spp 4 each sample's footprint is half a pixel: one level finer.
  Scene s4 = s;
  s4.render.spp = 4;
  RenderOptions o;
  o.spp = 4;
  const Image a = renderScene(s4, o);
  const glm::dvec2 uv((20 + 0.25 - 16) / 32.0, (20 + 0.25 - 16) / 32.0);  // sample (0, 0) of pixel (20, 20)
  const glm::dvec2 uv2((20 + 0.75 - 16) / 32.0, (20 + 0.25 - 16) / 32.0);
  const glm::dvec2 uv3((20 + 0.25 - 16) / 32.0, (20 + 0.75 - 16) / 32.0);
  const glm::dvec2 uv4((20 + 0.75 - 16) / 32.0, (20 + 0.75 - 16) / 32.0);
  const glm::dvec3 want = (c.lookup(uv, 3.0) + c.lookup(uv2, 3.0) + c.lookup(uv3, 3.0) + c.lookup(uv4, 3.0)) / 4.0;
  for (int q = 0; q < 3; ++q) EXPECT_NEAR(a.pixel(20, 20)[q], want[q], 1e-5);
}

// Trilinear differs from bilinear where the texture is minified, and not
// where it is magnified (lambda 0 is level 0's bilinear).
TEST(RendererTrilinear, EqualsBilinearWhenMagnified) {
  RenderOptions o;
  const Image tri = renderScene(headOnPlane(64, 0.5, TextureFilter::Trilinear), o);
  const Image bil = renderScene(headOnPlane(64, 0.5, TextureFilter::Bilinear), o);
  EXPECT_NE(tri.rgba, bil.rgba);
  // 2048 pixels across the plane: 512 / 2048 texels per pixel, magnified.
  Scene big = headOnPlane(256, 1.0, TextureFilter::Trilinear);
  big.camera.position.z = 1.0 / 8.0;  // the plane fills 8 x the image: a quarter texel per pixel
  Scene big_b = big;
  big_b.material.texture->filter = TextureFilter::Bilinear;
  EXPECT_EQ(renderScene(big, o).rgba, renderScene(big_b, o).rgba);
}

// normalize_normal false: the interpolated normal as it is. A Lambert
// sphere lit from the eye: each pixel is |sum b_k N_k| times the
// normalised one, at most 1 and, inside the triangles, less.
TEST(RendererUnnormalizedNormal, ScalesLambertByTheInterpolatedLength) {
  Scene s;
  s.camera.width = s.camera.height = 96;
  s.objects = {UvSphere{{0, 0, 0}, 1.0, 12, 6}};  // coarse: the interpolated normal is visibly short
  s.material.model = Lambert{};
  s.lights = {DirectionalLight{{0, 0, -1}, glm::dvec3(1.0)}};
  Scene raw = s;
  raw.normalize_normal = false;
  for (Precision p : {Precision::Double, Precision::Float}) {
    RenderOptions o;
    o.precision = p;
    const Image a = renderScene(s, o), b = renderScene(raw, o);
    double min_ratio = 1.0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
      if (a.rgba[i + 3] == 0 || a.rgba[i] < 0.05f) continue;
      const double r = double(b.rgba[i]) / a.rgba[i];
      EXPECT_LE(r, 1.0 + 1e-6);
      min_ratio = std::min(min_ratio, r);
    }
    // The 12 x 6 sphere's longest edge spans 60 degrees: the shortest
    // interpolated normal is about cos(30 deg) long.
    EXPECT_LT(min_ratio, 0.95) << toString(p);
    EXPECT_GT(min_ratio, 0.80) << toString(p);
  }
}
