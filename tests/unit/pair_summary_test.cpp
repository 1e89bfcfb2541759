// What the report's summary and the results file say of a failing pair
// (issue #36): the criterion it fails with its numbers, not only its max
// unexplained error; and results.json's shape requires that list.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "image/compare.h"
#include "image/pair_failure.h"
#include "validate/report/report.h"
#include "validate/results/results_shape.h"

namespace xval {
namespace {

using J = nlohmann::ordered_json;

// The summary of a pair read as the report reads each (validate/results/results.h).
std::string pairSummary(const J& p) { return xval::pairSummary(results::pairFromJson(p, "pair")); }

// A pair as the compare step writes it (validation/compare_step.cpp).
J pairRecord(const CompareMetrics& m, const Tolerance& t) {
  J p = {{"pair", "reference-gl"}};
  p["metrics"] = J::parse(toJson(m, t));
  p["pass"] = t.passes(m);
  p["failed"] = J::parse(failedJson(failedCriteria(m, t)).dump());
  return p;
}

Tolerance tolerance() {
  Tolerance t;
  t.max_abs = 2.0 / 65535.0, t.fraction = 0.999, t.max_unexplained = 128.0 / 65535.0;
  return t;
}

// The pair the report showed as "FAIL 3.76": 99.81% within, where 99.9%
// is needed, its largest unexplained error 3.76/65535 far under the cap.
TEST(PairSummary, AFailureOnTheFractionNamesTheFraction) {
  CompareMetrics m;
  m.width = m.height = 100;
  m.covered_both = 4769;
  m.fraction_within = 0.9981;
  m.max_unexplained = 3.76 / 65535.0;
  const J p = pairRecord(m, tolerance());
  ASSERT_FALSE(p["pass"].get<bool>());
  EXPECT_EQ(pairSummary(p), "FAIL fraction 99.81% < 99.9%");
}

TEST(PairSummary, AFailureOnTheCapNamesTheCap) {
  CompareMetrics m;
  m.width = m.height = 100;
  m.covered_both = 4769;
  m.max_unexplained = 300.0 / 65535.0;
  m.worst_unexplained_x = 3, m.worst_unexplained_y = 4;
  EXPECT_EQ(pairSummary(pairRecord(m, tolerance())), "FAIL unexplained 300.0 > 128");
}

TEST(PairSummary, APassShowsItsMaxUnexplainedError) {
  CompareMetrics m;
  m.width = m.height = 100;
  m.covered_both = 4769;
  m.max_unexplained = 3.76 / 65535.0;
  EXPECT_EQ(pairSummary(pairRecord(m, tolerance())), "PASS 3.76");
  EXPECT_EQ(pairSummary(J{{"pair", "a-b"}, {"error", "not compared: a render failed"}}), "ERROR");
}

// The fuzzing seed of a passing run (tests/fuzz/seeds/results/pass.json)
// has the shape; without "failed", or with a pair that fails listing
// nothing, it has not.
TEST(PairSummary, ResultsNeedTheFailedCriteriaOfEveryComparedPair) {
  std::ifstream in(std::string(XVAL_TESTS_DIR) + "/fuzz/seeds/results/pass.json");
  std::stringstream text;
  text << in.rdbuf();
  const J seed = J::parse(text.str());
  EXPECT_NO_THROW(checkResultsShape(seed, "pass.json"));
  J r = seed;
  r["cases"][0]["pairs"][0].erase("failed");
  EXPECT_THROW(checkResultsShape(r, "pass.json"), std::runtime_error);
  r = seed;
  r["cases"][0]["pairs"][0]["pass"] = false;
  EXPECT_THROW(checkResultsShape(r, "pass.json"), std::runtime_error);
  r["cases"][0]["pairs"][0]["failed"] = J::array({{{"key", "fraction"}, {"text", "t"}, {"brief", "b"}}});
  EXPECT_NO_THROW(checkResultsShape(r, "pass.json"));
  r["cases"][0]["pairs"][0]["failed"][0]["key"] = "other";
  EXPECT_THROW(checkResultsShape(r, "pass.json"), std::runtime_error);
}

}  // namespace
}  // namespace xval
