// The paper's Figure 1 verdicts (validate/paper_claims.h), judged from
// results.json's cases as the compare step stores them.
#include <gtest/gtest.h>

#include "validate/paper_claims.h"

namespace xval {
namespace {

using J = nlohmann::ordered_json;

J stats(double grey, double chroma, double hue) {
  return {{"lit_pixels", 100}, {"mean_chroma", chroma}, {"mean_albedo_chroma", 40.0},
          {"grey_fraction", grey}, {"hue_error_deg", hue}};
}

// Each claim exactly at its threshold (where it still holds).
J casesAtTheThresholds() {
  J cases = J::array();
  auto add = [&](const char* scene, J st) { cases.push_back({{"scene", scene}, {"colour_stats", st}}); };
  add("fig1_phong_front", stats(0.3, 20.0, 5.0));
  add("fig1_phong_behind", stats(0.8, 5.0, 3.0));
  add("fig1_phong_specular", stats(0.95, 0.0, 0.0));
  add("fig1_yiq_front", stats(0.0, 37.0, 7.0));      // 7 <= 5 + 2
  add("fig1_yiq_behind", stats(0.4, 5.5, 18.0));     // 0.8 >= 2 x 0.4 and 5.5 > 5
  add("fig1_yiq_specular", stats(0.2, 20.0, 15.0));  // 0.2 <= 0.2 and 15 <= 15
  add("light_spot", stats(0.5, 1.0, 1.0));           // not one of them
  return cases;
}

std::vector<bool> verdicts(const J& claims) {
  std::vector<bool> v;
  for (const auto& c : claims["claims"]) v.push_back(c["holds"].get<bool>());
  return v;
}

TEST(PaperClaims, EachClaimHoldsAtItsThreshold) {
  const J c = paperClaims(casesAtTheThresholds());
  ASSERT_FALSE(c.is_null());
  ASSERT_EQ(c["claims"].size(), 4u);
  EXPECT_EQ(verdicts(c), (std::vector<bool>{true, true, true, true}));
  EXPECT_EQ(c["scenes"].size(), 6u);
  EXPECT_EQ(c["scenes"][0], "fig1_phong_front");
  EXPECT_EQ(c["claims"][0]["measured"], "95.0%");
  for (const auto& claim : c["claims"]) {
    EXPECT_FALSE(claim["claim"].get<std::string>().empty());
    EXPECT_FALSE(claim["condition"].get<std::string>().empty());
  }
}

TEST(PaperClaims, EachClaimFailsJustPastItsThreshold) {
  struct Step { const char* scene; const char* field; double value; size_t claim; };
  for (const Step& s : {Step{"fig1_phong_specular", "grey_fraction", 0.9499, 0},
                        Step{"fig1_yiq_specular", "grey_fraction", 0.2001, 1},
                        Step{"fig1_yiq_specular", "hue_error_deg", 15.01, 1},
                        Step{"fig1_phong_behind", "grey_fraction", 0.7999, 2},
                        Step{"fig1_yiq_behind", "mean_chroma", 5.0, 2},
                        Step{"fig1_yiq_front", "hue_error_deg", 7.01, 3}}) {
    J cases = casesAtTheThresholds();
    for (auto& c : cases)
      if (c["scene"] == s.scene) c["colour_stats"][s.field] = s.value;
    std::vector<bool> expected(4, true);
    expected[s.claim] = false;
    EXPECT_EQ(verdicts(paperClaims(cases)), expected) << s.scene << "." << s.field << " = " << s.value;
  }
}

TEST(PaperClaims, NoneWithoutEveryFigure1Scene) {
  J cases = casesAtTheThresholds();
  cases.erase(cases.begin() + 4);  // fig1_yiq_behind
  EXPECT_TRUE(paperClaims(cases).is_null());
  // A Figure 1 case whose reference render failed has no colour_stats.
  cases = casesAtTheThresholds();
  cases[2].erase("colour_stats");
  EXPECT_TRUE(paperClaims(cases).is_null());
}

}  // namespace
}  // namespace xval
