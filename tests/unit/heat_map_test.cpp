// The heat map's scale (image/heat_map.h): its knots, its two segments,
// the colour of NaN and of uncovered pixels.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "image/heat_map.h"

using namespace xval;

namespace {
// Heat-map colours of a difference image whose pixel k has the channel
// difference e[k] (in 1/65535) in R, G and B, alpha 1; the last pixel is
// uncovered.
std::vector<glm::vec3> heatColours(const std::vector<double>& e) {
  Image d(int(e.size()) + 1, 1, false);
  for (size_t k = 0; k < e.size(); ++k) {
    float* p = d.pixel(int(k), 0);
    p[0] = p[1] = p[2] = float(e[k] / 65535.0), p[3] = 1.0f;
  }
  const Image h = heatMap(d);
  std::vector<glm::vec3> out;
  for (int k = 0; k < h.width; ++k) {
    const float* p = h.pixel(k, 0);
    EXPECT_EQ(p[3], 1.0f);
    out.emplace_back(p[0], p[1], p[2]);
  }
  return out;
}

void expectColour(glm::vec3 got, glm::vec3 want, const char* what) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-6) << what << " channel " << c;
}
}  // namespace

TEST(HeatMap, ScaleKnotsSegmentsNanAndUncovered) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // e = 0: t = 0, black. e = 0.5: t = 0.5/7 on the linear first seventh,
  // 6 t = 3/7 of the way from black to blue. e = 32: t = 1/7 + (6/7)(5/12)
  // = 1/2, the green knot. e = 4096 and beyond: white; NaN: white.
  const std::vector<double> e = {0.0, 0.5, 32.0, 4096.0, 1e9, nan};
  const std::vector<glm::vec3> c = heatColours(e);
  ASSERT_EQ(c.size(), e.size() + 1);
  expectColour(c[0], {0, 0, 0}, "e = 0");
  expectColour(c[1], {0, 0, 3.0f / 7.0f}, "e = 0.5");
  expectColour(c[2], {0, 1, 0}, "e = 32");
  expectColour(c[3], {1, 1, 1}, "e = 4096");
  expectColour(c[4], {1, 1, 1}, "e = 1e9");
  expectColour(c[5], {1, 1, 1}, "NaN");
  expectColour(c[6], glm::vec3(0.35f), "uncovered");
}

// Between knots the ramp is linear: halfway from green (t = 1/2) to
// yellow (t = 2/3), t = 7/12, is (0.5, 1, 0); e = 4096^((7/12 - 1/7) 7/6).
TEST(HeatMap, LinearBetweenKnots) {
  const double e = std::pow(4096.0, (7.0 / 12.0 - 1.0 / 7.0) * 7.0 / 6.0);
  expectColour(heatColours({e})[0], {0.5f, 1, 0}, "t = 7/12");
}

// A preview reduced by the block maximum keeps a single bad pixel (a box
// filter would divide it by k^2), at the block it falls in.
TEST(HeatMap, MaxDownscaledKeepsASinglePixel) {
  Image d(2000, 1000, false);
  d.pixel(1501, 777)[1] = 0.25f, d.pixel(1501, 777)[3] = 1.0f;
  const Image p = maxDownscaled(d, 1024);  // k = 2
  ASSERT_EQ(p.width, 1000);
  ASSERT_EQ(p.height, 500);
  EXPECT_EQ(p.pixel(750, 388)[1], 0.25f);
  EXPECT_EQ(p.pixel(750, 388)[3], 1.0f);
  EXPECT_EQ(p.pixel(750, 388)[0], 0.0f);
  EXPECT_EQ(p.pixel(751, 388)[1], 0.0f);
  // No larger than max_side: the image as it is.
  const Image same = maxDownscaled(d, 2000);
  EXPECT_EQ(same.width, 2000);
  EXPECT_EQ(same.pixel(1501, 777)[1], 0.25f);
  // An odd size rounds the output up: the last partial block is kept.
  Image odd(5, 3, false);
  odd.pixel(4, 2)[0] = 1.0f;
  const Image q = maxDownscaled(odd, 2);  // k = 3
  ASSERT_EQ(q.width, 2);
  ASSERT_EQ(q.height, 1);
  EXPECT_EQ(q.pixel(1, 0)[0], 1.0f);
}

// The ramp is the one OpenImageIO's color_map drew before xval drew it
// itself: the same float for every t (heat maps unchanged bit for bit).
TEST(HeatMap, RampIsOpenImageIosColorMapBitForBit) {
  namespace OIIO = OIIO_NAMESPACE;
  const float knots[] = {0, 0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 1, 1};
  std::vector<float> t;
  for (int i = -1000; i <= 101000; ++i) t.push_back(float(i) / 100000.0f);
  for (float x : {1.0f / 7.0f, 2.0f / 7.0f, 0.5f, 6.0f / 7.0f, std::nextafter(1.0f, 0.0f),
                  std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()})
    t.push_back(x);
  const OIIO::ImageBuf src(OIIO::ImageSpec(int(t.size()), 1, 1, OIIO::TypeDesc::FLOAT), t.data());
  const OIIO::ImageBuf out = OIIO::ImageBufAlgo::color_map(src, 0, 7, 3, knots);
  std::vector<float> want(t.size() * 3);
  ASSERT_TRUE(out.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, want.data())) << out.geterror();
  int wrong = 0;
  for (size_t i = 0; i < t.size(); ++i) {
    float got[3];
    heatRampColour(t[i], got);
    for (int c = 0; c < 3; ++c)
      if (std::memcmp(&got[c], &want[i * 3 + c], sizeof(float)) != 0 && ++wrong <= 5)
        ADD_FAILURE() << "t = " << t[i] << " channel " << c << ": " << got[c] << ", color_map " << want[i * 3 + c];
  }
  EXPECT_EQ(wrong, 0);
}
