#include "validate/paper_claims.h"

#include <cstdio>
#include <string>

#include "text/number_text.h"

namespace xval {

namespace {

std::string fmt(double v, int prec) { return fixed(v, prec); }

const nlohmann::ordered_json* statsOf(const nlohmann::ordered_json& cases, const char* scene) {
  for (const auto& c : cases)
    if (c.value("scene", "") == scene && c.contains("colour_stats")) return &c["colour_stats"];
  return nullptr;
}

}  // namespace

nlohmann::ordered_json paperClaims(const nlohmann::ordered_json& cases) {
  using J = nlohmann::ordered_json;
  const J* st[6];
  for (int i = 0; i < 6; ++i)
    if (!(st[i] = statsOf(cases, kFigure1Scenes[i]))) return nullptr;  // not in this run
  auto v = [&](int i, const char* k) { return (*st[i])[k].get<double>(); };
  enum { PhongFront, PhongBehind, PhongSpecular, YiqFront, YiqBehind, YiqSpecular };
  J claims = J::array();
  auto claim = [&](const char* text, const char* condition, const std::string& measured, bool holds) {
    claims.push_back({{"claim", text}, {"condition", condition}, {"measured", measured}, {"holds", holds}});
  };
  claim("Specular only, classic Phong is grey whatever the texture", "grey share of fig1_phong_specular >= 95%",
        fmt(100 * v(PhongSpecular, "grey_fraction"), 1) + "%", v(PhongSpecular, "grey_fraction") >= 0.95);
  claim("Specular only, the YIQ model follows the texture",
        "grey share of fig1_yiq_specular <= 20% and hue error <= 15 deg",
        fmt(100 * v(YiqSpecular, "grey_fraction"), 1) + "%, " + fmt(v(YiqSpecular, "hue_error_deg"), 1) + " deg",
        v(YiqSpecular, "grey_fraction") <= 0.2 && v(YiqSpecular, "hue_error_deg") <= 15.0);
  claim("Light behind, classic Phong greys out and YIQ does not",
        "grey share: phong_behind >= 2 x yiq_behind, and mean C*: yiq_behind > phong_behind",
        fmt(100 * v(PhongBehind, "grey_fraction"), 1) + "% vs " + fmt(100 * v(YiqBehind, "grey_fraction"), 1) +
            "%; C* " + fmt(v(YiqBehind, "mean_chroma"), 1) + " vs " + fmt(v(PhongBehind, "mean_chroma"), 1),
        v(PhongBehind, "grey_fraction") >= 2 * v(YiqBehind, "grey_fraction") &&
            v(YiqBehind, "mean_chroma") > v(PhongBehind, "mean_chroma"));
  claim("Light in front, YIQ is no worse than classic Phong", "hue error: yiq_front <= phong_front + 2 deg",
        fmt(v(YiqFront, "hue_error_deg"), 2) + " vs " + fmt(v(PhongFront, "hue_error_deg"), 2) + " deg",
        v(YiqFront, "hue_error_deg") <= v(PhongFront, "hue_error_deg") + 2.0);
  J scenes = J::array();
  for (const char* s : kFigure1Scenes) scenes.push_back(s);
  return {{"scenes", scenes}, {"claims", claims}};
}

}  // namespace xval
