// image/compare.h: the one nearest-rank percentile, and the metrics over
// the pixels either image covers, on hand-made values and images.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "image/compare.h"

using namespace xval;

TEST(NearestRankPercentile, IsTheCeilPnThSmallest) {
  std::vector<double> v;
  for (int i = 1000; i >= 1; --i) v.push_back(double(i));  // any order
  EXPECT_EQ(nearestRankPercentile(v, 0.999), 999.0);       // ceil(999.0) = 999th
  EXPECT_EQ(nearestRankPercentile(v, 1.0), 1000.0);
  EXPECT_EQ(nearestRankPercentile(v, 0.5), 500.0);
  EXPECT_EQ(nearestRankPercentile(v, 0.0005), 1.0);  // ceil(0.5) = 1st
  // Fewer than 1000 values: p99.9 is the largest.
  EXPECT_EQ(nearestRankPercentile({3.0, 1.0, 2.0}, 0.999), 3.0);
  EXPECT_EQ(nearestRankPercentile({4.0, 1.0, 3.0, 2.0}, 0.5), 2.0);  // ceil(2) = 2nd, not the mean 2.5
  EXPECT_EQ(nearestRankPercentile({7.0}, 0.25), 7.0);
  EXPECT_EQ(nearestRankPercentile({}, 0.999), 0.0);
  EXPECT_THROW(nearestRankPercentile({1.0}, 0.0), std::invalid_argument);
  EXPECT_THROW(nearestRankPercentile({1.0}, 1.5), std::invalid_argument);
  EXPECT_THROW(nearestRankPercentile({1.0}, std::nan("")), std::invalid_argument);
}

namespace {
void set(Image& im, int x, int y, float r, float g, float b, float a) {
  float* p = im.pixel(x, y);
  p[0] = r, p[1] = g, p[2] = b, p[3] = a;
}
}  // namespace

// Both-covered metrics leave a pixel one image misses out (a mask
// disagreement); the either-covered ones count it with its whole colour.
TEST(CompareMetrics, EitherCoveredCountsMaskDisagreementsWithTheirColour) {
  Image a(2, 2, false), b(2, 2, false);
  set(a, 0, 0, 0.5f, 0.5f, 0.5f, 1.0f);
  set(b, 0, 0, 0.5f, 0.5f, 0.5f + 8.0f / 65535.0f, 1.0f);  // 8/65535 in blue
  set(a, 1, 0, 0.3f, 0.0f, 0.0f, 1.0f);                     // covered by a only
  // (0,1) and (1,1): covered by neither.
  const CompareMetrics m = compareImages(a, b, Tolerance{});
  EXPECT_EQ(m.covered_both, 1);
  EXPECT_EQ(m.mask_disagree, 1);
  EXPECT_NEAR(m.max_abs * 65535.0, 8.0, 1e-3);
  EXPECT_EQ(m.covered_either, 2);
  EXPECT_NEAR(m.max_abs_either, 0.3, 1e-7);
  EXPECT_NEAR(m.p999_abs_either, 0.3, 1e-7);  // nearest rank of 2 values: the larger
  const double d = 8.0 / 65535.0;
  EXPECT_NEAR(m.rmse_either, std::sqrt((d * d + 0.3 * 0.3) / 6.0), 1e-7);
  // The one JSON form carries both.
  const auto j = metricsJson(m);
  EXPECT_EQ(j.at("covered_both").get<long long>(), 1);
  EXPECT_EQ(j.at("either_covered").at("pixels").get<long long>(), 2);
  EXPECT_NEAR(j.at("either_covered").at("max_abs_16bit").get<double>(), 0.3 * 65535.0, 0.01);
  // Nothing covered: zero, and no NaN in the record.
  const CompareMetrics z = compareImages(Image(2, 2, false), Image(2, 2, false), Tolerance{});
  EXPECT_EQ(z.covered_either, 0);
  EXPECT_EQ(z.rmse_either, 0.0);
}
