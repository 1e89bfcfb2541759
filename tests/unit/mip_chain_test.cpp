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

// Texel (x, y) of a W x H texture with pseudo-random values in [0, 1):
// no structure a wrong rule could hide behind.
Texture noise(int w, int h) {
  Texture t;
  t.width = w, t.height = h;
  unsigned s = 12345u;
  for (int k = 0; k < w * h * 3; ++k) {
    s = s * 1664525u + 1013904223u;
    t.rgb.push_back(float(s >> 8) / 16777216.0f);
  }
  return t;
}

// Where texel i of a level n wide samples the level w wide above it
// (mip_chain.h), in the form the rule states it.
double sampleAt(int i, int w, int n) { return (i + 0.5) * w / n - 0.5; }

// Every texel of level k + 1 of a ramp is the ramp of level k at the
// texel's sample point (bilinear interpolation of a linear function is
// exact), so the whole chain's sample points are checked at once.
void expectRampChain(int w, int h) {
  const MipChain c = mipChain(ramp(w, h));
  int q = 0;
  while (std::max(w, h) >> (q + 1)) ++q;
  ASSERT_EQ(c.maxLevel(), q) << w << " x " << h;
  // The ramp of each level: texel (i, j) = (a + b i, d + e j, ...).
  double a = 0, b = 1, d = 0, e = 1;
  for (int k = 1; k <= q; ++k) {
    const Texture& s = c.levels[size_t(k - 1)];
    const Texture& n = c.levels[size_t(k)];
    ASSERT_EQ(n.width, std::max(1, s.width / 2));
    ASSERT_EQ(n.height, std::max(1, s.height / 2));
    // The new ramp: x(i) = a + b * sampleAt(i) is linear in i.
    const double a1 = a + b * sampleAt(0, s.width, n.width);
    const double b1 = n.width > 1 ? b * (sampleAt(1, s.width, n.width) - sampleAt(0, s.width, n.width)) : 0.0;
    const double d1 = d + e * sampleAt(0, s.height, n.height);
    const double e1 = n.height > 1 ? e * (sampleAt(1, s.height, n.height) - sampleAt(0, s.height, n.height)) : 0.0;
    a = a1, b = b1, d = d1, e = e1;
    for (int j = 0; j < n.height; ++j)
      for (int i = 0; i < n.width; ++i) {
        const double x = a + b * i, y = d + e * j;
        const glm::vec3 v = n.texel(i, j);
        EXPECT_NEAR(v.x, x, 2e-5) << w << " x " << h << " level " << k << " texel " << i << "," << j;
        EXPECT_NEAR(v.y, y, 2e-5) << w << " x " << h << " level " << k << " texel " << i << "," << j;
        EXPECT_NEAR(v.z, x + 10 * y, 2e-4) << w << " x " << h << " level " << k << " texel " << i << "," << j;
      }
  }
}

}  // namespace

// 5 x 3 -> 2 x 1 -> 1 x 1. Level 1 texel i samples level 0 at
// x = (i + 1/2) 5/2 - 1/2 = 0.75, 3.25 and y = (1/2) 3 - 1/2 = 1: the
// whole level, the odd last column and row included (the earlier rule,
// a 2x2 box that left them out, gave (0.5, 0.5, 5.5) and (2.5, 0.5, 7.5)).
TEST(MipChain, HalvesWithFloorAndResamplesTheWholeLevel) {
  const MipChain c = mipChain(ramp(5, 3));
  ASSERT_EQ(c.levels.size(), 3u);  // q = floor(log2(5)) = 2
  EXPECT_EQ(c.levels[1].width, 2);
  EXPECT_EQ(c.levels[1].height, 1);
  EXPECT_EQ(c.levels[2].width, 1);
  EXPECT_EQ(c.levels[2].height, 1);
  EXPECT_EQ(c.levels[1].texel(0, 0), glm::vec3(0.75f, 1.0f, 10.75f));
  EXPECT_EQ(c.levels[1].texel(1, 0), glm::vec3(3.25f, 1.0f, 13.25f));
  // Level 2 from level 1's 2 x 1: x = 1/2 (the mean of its two texels),
  // y = 0 (its one row).
  EXPECT_EQ(c.levels[2].texel(0, 0), glm::vec3(2.0f, 1.0f, 12.0f));
}

// The generated set's noise16_37x23: 37 x 23 -> 18 x 11 -> 9 x 5 -> 4 x 2
// -> 2 x 1 -> 1 x 1, odd on both axes at level 0.
TEST(MipChain, OddSizesSampleEveryColumnAndRow) {
  expectRampChain(37, 23);
  const MipChain c = mipChain(ramp(37, 23));
  const int sizes[][2] = {{37, 23}, {18, 11}, {9, 5}, {4, 2}, {2, 1}, {1, 1}};
  ASSERT_EQ(c.levels.size(), 6u);
  for (size_t k = 0; k < 6; ++k) {
    EXPECT_EQ(c.levels[k].width, sizes[k][0]) << k;
    EXPECT_EQ(c.levels[k].height, sizes[k][1]) << k;
  }
  // Level 1's last texel (17, 10) reaches into level 0's last column and
  // row: x = 17.5 * 37/18 - 1/2 = 35 + 17/36, y = 10.5 * 23/11 - 1/2 = 21 + 10/22.
  const glm::vec3 last = c.levels[1].texel(17, 10);
  EXPECT_FLOAT_EQ(last.x, float(35.0 + 17.0 / 36.0));
  EXPECT_FLOAT_EQ(last.y, float(21.0 + 10.0 / 22.0));
}

// A hand computation on values with no structure: level 1 texel (17, 10)
// of a 37 x 23 texture takes texels x 35, 36 at weights 19/36, 17/36 and
// y 21, 22 at 12/22, 10/22 (from the sample point above).
TEST(MipChain, OddLevelTexelIsTheBilinearMixOfItsFourTaps) {
  const Texture t = noise(37, 23);
  const MipChain c = mipChain(t);
  const double wx0 = 19.0 / 36.0, wx1 = 17.0 / 36.0, wy0 = 12.0 / 22.0, wy1 = 10.0 / 22.0;
  const glm::dvec3 want = wx0 * wy0 * glm::dvec3(t.texel(35, 21)) + wx1 * wy0 * glm::dvec3(t.texel(36, 21)) +
                          wx0 * wy1 * glm::dvec3(t.texel(35, 22)) + wx1 * wy1 * glm::dvec3(t.texel(36, 22));
  const glm::vec3 got = c.levels[1].texel(17, 10);
  for (int q = 0; q < 3; ++q) EXPECT_FLOAT_EQ(got[q], float(want[q])) << q;
  // Texel (0, 0): x = 1/2 * 37/18 - 1/2 = 19/36, y = 1/2 * 23/11 - 1/2 = 6/11.
  const double fx = 19.0 / 36.0, fy = 6.0 / 11.0;
  const glm::dvec3 want0 = (1 - fx) * (1 - fy) * glm::dvec3(t.texel(0, 0)) + fx * (1 - fy) * glm::dvec3(t.texel(1, 0)) +
                           (1 - fx) * fy * glm::dvec3(t.texel(0, 1)) + fx * fy * glm::dvec3(t.texel(1, 1));
  const glm::vec3 got0 = c.levels[1].texel(0, 0);
  for (int q = 0; q < 3; ++q) EXPECT_FLOAT_EQ(got0[q], float(want0[q])) << q;
}

// One texel wide or high: that axis stays at its one column or row, the
// other is resampled as above (1 x 7 -> 1 x 3 -> 1 x 1: level 2 is level
// 1's middle texel, y = (1/2) 3 - 1/2 = 1).
TEST(MipChain, OneWideAndOneHighTextures) {
  expectRampChain(1, 7);
  expectRampChain(7, 1);
  expectRampChain(1, 8);
  expectRampChain(13, 1);
  const Texture t = noise(1, 7);
  const MipChain c = mipChain(t);
  ASSERT_EQ(c.levels.size(), 3u);
  EXPECT_EQ(c.levels[2].texel(0, 0), c.levels[1].texel(0, 1));
  const MipChain r = mipChain(noise(7, 1));
  EXPECT_EQ(r.levels[2].texel(0, 0), r.levels[1].texel(1, 0));
}

// Even sides: the sample point is 2i + 1/2, the mean of the 2x2 block,
// bit for bit the box filter ((a + b) + c + d) / 4 in double, rounded once.
TEST(MipChain, EvenSizesAreTheTwoByTwoBoxBitForBit) {
  for (const auto& wh : {std::pair{64, 32}, std::pair{16, 16}, std::pair{12, 6}}) {
    const MipChain c = mipChain(noise(wh.first, wh.second));
    for (size_t k = 1; k < c.levels.size(); ++k) {
      const Texture& s = c.levels[k - 1];
      if (s.width % 2 || s.height % 2) break;  // 12 x 6 -> 6 x 3: odd from here
      const Texture& n = c.levels[k];
      for (int j = 0; j < n.height; ++j)
        for (int i = 0; i < n.width; ++i) {
          const glm::dvec3 box = (glm::dvec3(s.texel(2 * i, 2 * j)) + glm::dvec3(s.texel(2 * i + 1, 2 * j)) +
                                  glm::dvec3(s.texel(2 * i, 2 * j + 1)) + glm::dvec3(s.texel(2 * i + 1, 2 * j + 1))) /
                                 4.0;
          EXPECT_EQ(n.texel(i, j), glm::vec3(box)) << wh.first << " x " << wh.second << " level " << k << " " << i << "," << j;
        }
    }
  }
  // A power-of-two chain down to its 1-wide levels (64 x 16 -> ... -> 4 x 1
  // -> 2 x 1 -> 1 x 1): the one row counts as both rows of the box.
  const MipChain c = mipChain(noise(64, 16));
  for (size_t k = 5; k < c.levels.size(); ++k) {
    const Texture& s = c.levels[k - 1];
    const Texture& n = c.levels[k];
    ASSERT_EQ(s.height, 1);
    for (int i = 0; i < n.width; ++i) {
      const glm::dvec3 a(s.texel(2 * i, 0)), b(s.texel(2 * i + 1, 0));
      EXPECT_EQ(n.texel(i, 0), glm::vec3((a + b + a + b) / 4.0)) << "level " << k << " " << i;
    }
  }
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
