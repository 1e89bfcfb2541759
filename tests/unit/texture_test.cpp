// Texture lookups: orientation, texel centres, wrap, nearest and bilinear.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "texture/brick.h"
#include "texture/texture.h"

using namespace xval;

namespace {
// 2x2: top-left red, top-right green, bottom-left blue, bottom-right white.
Texture quad() {
  Texture t;
  t.width = t.height = 2;
  t.rgb = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  return t;
}
}  // namespace

TEST(Texture, NearestUsesTopLeftOriginAndWraps) {
  Texture t = quad();
  auto f = TextureFilter::Nearest;
  EXPECT_EQ(t.lookup(glm::dvec2(0.25, 0.25), f), glm::dvec3(1, 0, 0));
  EXPECT_EQ(t.lookup(glm::dvec2(0.75, 0.25), f), glm::dvec3(0, 1, 0));
  EXPECT_EQ(t.lookup(glm::dvec2(0.25, 0.75), f), glm::dvec3(0, 0, 1));
  EXPECT_EQ(t.lookup(glm::dvec2(1.25, -0.25), f), glm::dvec3(0, 0, 1));  // wrap
  EXPECT_EQ(t.lookup(glm::dvec2(1.0, 1.0), f), glm::dvec3(1, 0, 0));    // frac -> 0
}

TEST(Texture, BilinearIsExactAtTexelCentresAndBlendsBetween) {
  Texture t = quad();
  auto f = TextureFilter::Bilinear;
  EXPECT_EQ(t.lookup(glm::dvec2(0.25, 0.25), f), glm::dvec3(1, 0, 0));
  EXPECT_EQ(t.lookup(glm::dvec2(0.75, 0.75), f), glm::dvec3(1, 1, 1));
  // Halfway between red and green texel centres.
  glm::dvec3 mid = t.lookup(glm::dvec2(0.5, 0.25), f);
  EXPECT_NEAR(mid.r, 0.5, 1e-15);
  EXPECT_NEAR(mid.g, 0.5, 1e-15);
  // At u = 0 the wrap blends the last column with the first.
  glm::dvec3 edge = t.lookup(glm::dvec2(0.0, 0.25), f);
  EXPECT_NEAR(edge.r, 0.5, 1e-15);
  EXPECT_NEAR(edge.g, 0.5, 1e-15);
}

TEST(Texture, BrickIs512SquareWith8BitCodesAndTiles) {
  Texture t = makeBrickTexture();
  EXPECT_EQ(t.width, 512);
  EXPECT_EQ(t.height, 512);
  ASSERT_EQ(t.rgb8.size(), 512u * 512u * 3u);
  for (size_t i = 0; i < t.rgb.size(); i += 997) EXPECT_EQ(t.rgb[i], t.rgb8[i] / 255.0f);
  // Mortar rows at the top and after every 64 px course.
  EXPECT_GT(t.texel(200, 0).g, 0.6f);
  EXPECT_GT(t.texel(200, 64).g, 0.6f);
  EXPECT_LT(t.texel(200, 30).g, 0.45f);  // inside a brick
  // Deterministic: two calls give the same bytes.
  EXPECT_EQ(makeBrickTexture().rgb8, t.rgb8);
}

// pack(): the compact copy returns bit-identical texels, and is refused when
// the float values are not a function of the 8-bit codes.
TEST(Texture, PackedTexelsAreBitIdenticalAndOnlyWhenExact) {
  xval::Texture t = xval::makeBrickTexture();
  xval::Texture p = t;
  p.pack();
  ASSERT_EQ(p.packed.size(), size_t(t.width) * t.height);
  for (int y = 0; y < t.height; y += 7)
    for (int x = 0; x < t.width; x += 5) {
      const glm::vec3 a = t.texel(x, y), b = p.texel(x, y);
      EXPECT_EQ(a.x, b.x);
      EXPECT_EQ(a.y, b.y);
      EXPECT_EQ(a.z, b.z);
    }
  EXPECT_TRUE(p.codes_are_c_over_255);  // the brick's values are c / 255
  xval::Texture q = t;
  q.rgb.back() = std::nextafter(q.rgb.back(), 2.0f);  // same code, another value
  q.pack();
  EXPECT_TRUE(q.packed.empty());
  EXPECT_FALSE(q.codes_are_c_over_255);
  // Every value of one code moved alike: still a function of the code
  // (packed), but no longer c / 255.
  xval::Texture r = t;
  for (size_t i = 0; i < r.rgb.size(); ++i)
    if (r.rgb8[i] == r.rgb8[0]) r.rgb[i] = std::nextafter(r.rgb[i], 2.0f);
  r.pack();
  EXPECT_FALSE(r.packed.empty());
  EXPECT_FALSE(r.codes_are_c_over_255);
}

// A uv that is not finite (a huge uv_repeat overflows float to inf; inf -
// floor(inf) is NaN) looks up the texel at frac 0, in both filters and
// precisions, as a uv beyond float's integers (3e38, whose frac is 0) does.
// Before, NaN reached int(fu * width): a texel index out of the image
// (`xval render --precision float` crashed with SIGSEGV).
TEST(Texture, NonFiniteUvLooksUpFracZero) {
  Texture t = makeBrickTexture();
  for (TextureFilter f : {TextureFilter::Nearest, TextureFilter::Bilinear}) {
    const glm::vec3 at0 = t.lookup(glm::vec2(0.0f), f);
    const glm::dvec3 at0d = t.lookup(glm::dvec2(0.0), f);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::nanf("");
    for (float u : {inf, -inf, nan, 3e38f, -3e38f}) {
      SCOPED_TRACE(u);
      EXPECT_EQ(t.lookup(glm::vec2(u, 0.0f), f), at0);
      EXPECT_EQ(t.lookup(glm::vec2(0.0f, u), f), at0);
      EXPECT_EQ(t.lookup(glm::vec2(u, u), f), at0);
      EXPECT_EQ(t.lookup(glm::dvec2(double(u), double(u)), f), at0d);
    }
  }
}
