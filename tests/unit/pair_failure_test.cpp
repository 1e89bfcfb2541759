// failedCriteria (image/pair_failure.h): every failing criterion, in its
// order, with its numbers; none exactly when Tolerance::passes.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "image/pair_failure.h"

namespace xval {
namespace {

std::vector<std::string> keys(const std::vector<PairFailure>& f) {
  std::vector<std::string> k;
  for (const PairFailure& p : f) k.push_back(p.key);
  return k;
}

// 4769 covered pixels, 8 of them outside 2/65535, the largest unexplained
// error 3.76/65535 under a cap of 128/65535: the pair the report showed as
// "FAIL 3.76" (issue #36).
CompareMetrics fractionOnly() {
  CompareMetrics m;
  m.width = m.height = 100;
  m.covered_both = 4769;
  m.fraction_within = double(4769 - 8) / 4769.0;
  m.max_unexplained = 3.76 / 65535.0;
  m.worst_unexplained_x = 5, m.worst_unexplained_y = 6;
  return m;
}

Tolerance tolerance() {
  Tolerance t;
  t.max_abs = 2.0 / 65535.0, t.fraction = 0.999, t.max_unexplained = 16.0 / 65535.0;
  return t;
}

TEST(PairFailure, TheFractionAloneIsNamedWithItsNumbers) {
  const auto f = failedCriteria(fractionOnly(), tolerance());
  ASSERT_EQ(keys(f), std::vector<std::string>{"fraction"});
  EXPECT_EQ(f[0].text, "fraction within tolerance 99.83% < 99.9% (8 of 4769 pixels outside)");
  EXPECT_EQ(f[0].brief, "fraction 99.83% < 99.9%");
  EXPECT_TRUE(failsOnlyOnFraction(f));
}

TEST(PairFailure, EveryCriterionInItsOrder) {
  CompareMetrics m = fractionOnly();
  m.covered_both = 0;
  m.mask_disagree = 5, m.mask_disagree_explained = 2;
  m.max_unexplained = 37.0 / 65535.0, m.worst_unexplained_x = 78, m.worst_unexplained_y = 72;
  const auto f = failedCriteria(m, tolerance());
  ASSERT_EQ(keys(f), (std::vector<std::string>{"nothing_covered", "mask", "unexplained_cap", "fraction"}));
  EXPECT_EQ(f[0].text, "no pixel covered by both");
  EXPECT_EQ(f[1].text, "3 mask disagreements no edge explains");
  EXPECT_EQ(f[2].text, "unexplained error 37.0/65535 > cap 16/65535 at (78, 72)");
  EXPECT_EQ(f[2].brief, "unexplained 37.0 > 16");
  EXPECT_FALSE(failsOnlyOnFraction(f));
  EXPECT_FALSE(failsOnlyOnFraction({}));
}

// A value just past its bound is shown with the digits that put it there.
TEST(PairFailure, NumbersNeverReadAsTheBound) {
  CompareMetrics m = fractionOnly();
  m.fraction_within = 0.998999;
  m.max_unexplained = 16.004 / 65535.0;
  const auto f = failedCriteria(m, tolerance());
  ASSERT_EQ(keys(f), (std::vector<std::string>{"unexplained_cap", "fraction"}));
  EXPECT_EQ(f[0].brief, "unexplained 16.004 > 16");
  EXPECT_EQ(f[1].brief, "fraction 99.8999% < 99.9%");
}

// failedCriteria is empty exactly when Tolerance::passes, over metrics
// that vary every criterion around its bound (NaN and infinity too).
TEST(PairFailure, EmptyExactlyWhenThePairPasses) {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const Tolerance t = tolerance();
  int passing = 0, failing = 0;
  for (long long covered : {0LL, 1LL, 4769LL})
    for (long long mask : {0LL, 1LL, 3LL})
      for (long long explained : {0LL, 1LL, 3LL})
        for (double unexplained : {0.0, t.max_unexplained, std::nextafter(t.max_unexplained, 1.0), 1.0, inf, nan})
          for (double fraction : {1.0, t.fraction, std::nextafter(t.fraction, 0.0), 0.5, 0.0, nan}) {
            CompareMetrics m;
            m.covered_both = covered, m.mask_disagree = mask, m.mask_disagree_explained = explained;
            m.max_unexplained = unexplained, m.fraction_within = fraction;
            const auto f = failedCriteria(m, t);
            EXPECT_EQ(f.empty(), t.passes(m)) << "covered " << covered << " mask " << mask << "/" << explained
                                              << " unexplained " << unexplained << " fraction " << fraction;
            (t.passes(m) ? passing : failing)++;
          }
  EXPECT_GT(passing, 0);
  EXPECT_GT(failing, 0);
}

TEST(PairFailure, JsonListsEveryFailure) {
  const auto j = failedJson(failedCriteria(fractionOnly(), tolerance()));
  ASSERT_EQ(j.size(), 1u);
  EXPECT_EQ(j[0]["key"], "fraction");
  EXPECT_EQ(j[0]["text"], "fraction within tolerance 99.83% < 99.9% (8 of 4769 pixels outside)");
  EXPECT_TRUE(failedJson({}).is_array());
  EXPECT_TRUE(failedJson({}).empty());
}

}  // namespace
}  // namespace xval
