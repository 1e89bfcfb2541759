// The luma-only mode (colour/luma_only.h, docs/models.md "Luma-only
// lighting"): its identities with the paper's listing and the yiq_luma
// model, the chroma it keeps in each space, its parse errors, and the
// YUV-vs-YIQ difference the docs quote.
#include <gtest/gtest.h>

#include <cstdio>

#include "scene_file/precision_limits.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"
#include "shading/shader.h"

using namespace xval;
using glm::dvec3;

namespace {

Material material(LightingModel m, std::optional<LumaSpace> s) {
  Material mat;
  mat.model = m;
  mat.luma_only = s;
  return mat;
}
const dvec3 kN(0, 0, 1), kV(0, 0, 1), kP(0);
const dvec3 kColours[] = {{0.5, 0.25, 0.1}, {0.1, 0.8, 0.3}, {0.9, 0.9, 0.9}, {0.2, 0.3, 0.95}, {0, 0, 0}};
// Light directions in the x-z plane at these angles from N (degrees).
const double kAngles[] = {0, 20, 45, 70, 89, 100};
dvec3 lightAt(double deg) {
  const double r = deg * 3.14159265358979323846 / 180.0;
  return {2 * std::sin(r), 0, 2 * std::cos(r)};
}

// CIELAB of a linear RGB colour (colour/cie.h's white point).
dvec3 lab(dvec3 c) {
  const dvec3 t = colour::relativeXyz(c);
  const dvec3 f(colour::labF(t.x), colour::labF(t.y), colour::labF(t.z));
  return {116 * f.y - 16, 500 * (f.x - f.y), 200 * (f.y - f.z)};
}

}  // namespace

// The issue's identity: Lambert in the luma-only mode (yiq) is the listing's
// diffuse, LumaPhongDiffuse with Specular 0 and no "- 0.1", computed as the
// listing does (RGB -> YIQ, Y' = Y Dl, YIQ -> RGB), where Dl = A_Y + Y(Lc)
// sat(N.L) stays below the listing's saturate.
TEST(LumaOnly, LambertInYiqIsTheListingsDiffuse) {
  const dvec3 light_colour(0.9, 0.7, 0.5), ambient(0.05, 0.1, 0.02);
  for (double deg : kAngles)
    for (dvec3 c : kColours) {
      Shader<double> sh(material(Lambert{}, LumaSpace::Yiq),
                        {PointLight{lightAt(deg), light_colour, {}}, AmbientLight{ambient}});
      const double x = std::max(0.0, glm::dot(kN, glm::normalize(lightAt(deg))));
      const double dl = models::lightLuma(ambient) + models::lightLuma(light_colour) * x;
      ASSERT_LT(dl, 1.0);
      const dvec3 want = models::yiqLumaListing(c, dl, 0.0, 0.0);
      const dvec3 got = sh.shade(kP, kN, kV, c);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-7) << deg << " deg, channel " << k;
    }
}

// yiq_luma = classic_phong (paper, ka 1) in the luma-only mode yiq, minus
// luma_offset, wherever the listing's Dl is not saturated; where it is
// (A_Y + kd Y(Lc) N.L > 1) they differ by Y (that sum - 1).
TEST(LumaOnly, YiqLumaIsClassicPhongPaperInYiqLessTheOffsetBelowDlsSaturate) {
  YiqLuma y;
  y.kd = 0.6, y.ks = 0.7, y.shininess = 8, y.luma_offset = 0.1;
  ClassicPhong p;
  p.ka = 1, p.kd = 0.6, p.ks = 0.7, p.shininess = 8;
  const std::vector<Light> lights = {PointLight{lightAt(30), dvec3(1.0, 0.8, 0.6), {}}, AmbientLight{dvec3(0.1)}};
  Shader<double> a(material(y, std::nullopt), lights), b(material(p, LumaSpace::Yiq), lights);
  for (double deg : {0.0, 15.0, 30.0, 60.0})
    for (dvec3 c : kColours) {
      const dvec3 v = glm::normalize(dvec3(std::sin(deg * 0.0174533), 0, std::cos(deg * 0.0174533)));
      const dvec3 want = a.shade(kP, kN, v, c), got = b.shade(kP, kN, v, c) - dvec3(y.luma_offset);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-12);
    }
  // The listing's saturate: one white light head on, A = 0.1, kd = 1: the
  // sum is 1.1, Dl = 1; the luma-only Phong keeps 1.1.
  const std::vector<Light> bright = {PointLight{{0, 0, 2}, dvec3(1.0), {}}, AmbientLight{dvec3(0.1)}};
  YiqLuma y1;
  y1.ks = 0;
  ClassicPhong p1;
  p1.ks = 0;
  const dvec3 c = kColours[0];
  const dvec3 d = Shader<double>(material(p1, LumaSpace::Yiq), bright).shade(kP, kN, kV, c) - dvec3(0.1) -
                  Shader<double>(material(y1, std::nullopt), bright).shade(kP, kN, kV, c);
  EXPECT_NEAR(d.x, colour::luma(c) * 0.1, 1e-12);
}

// Both spaces keep the chroma of C (I, Q; a*, b*) and set the luma to that
// of the model lit in grey, for a model with coloured parameters and a
// coloured light.
TEST(LumaOnly, KeepsChromaAndTakesTheLumaOfTheGreyLitModel) {
  Trilight t;
  t.c0 = {1.0, 0.6, 0.3}, t.c1 = {0.1, 0.2, 0.3}, t.c2 = {0.05, 0.0, 0.1};
  const std::vector<Light> lights = {PointLight{lightAt(40), dvec3(0.9, 0.5, 0.8), {}}, AmbientLight{dvec3(0.1)}};
  for (LumaSpace s : {LumaSpace::Yiq, LumaSpace::CieLstar}) {
    Shader<double> sh(material(t, s), lights);
    Shader<double> grey(material(t, std::nullopt), greyLights(lights, s));
    for (dvec3 c : kColours) {
      if (c == dvec3(0)) continue;
      const dvec3 f = sh.shade(kP, kN, kV, c);
      const double y_c = luma_only::surfaceLuma(s, c);
      const double y_out = luma_only::lightLuma(s, grey.shade(kP, kN, kV, dvec3(y_c)));
      EXPECT_GT(std::abs(y_out - y_c), 0.05);  // the lighting changes the luma
      if (s == LumaSpace::Yiq) {
        const dvec3 yiq_f = colour::rgbToYiq(f), yiq_c = colour::rgbToYiq(c);
        EXPECT_NEAR(yiq_f.y, yiq_c.y, 1e-7);
        EXPECT_NEAR(yiq_f.z, yiq_c.z, 1e-7);
        EXPECT_NEAR(colour::luma(f), y_out, 1e-7);
      } else {
        const dvec3 lf = lab(f), lc = lab(c);
        EXPECT_NEAR(lf.y, lc.y, 1e-9);
        EXPECT_NEAR(lf.z, lc.z, 1e-9);
        EXPECT_NEAR(lf.x, colour::lightness(y_out), 1e-9);
      }
    }
  }
}

// A model that returns C (only a white ambient light of 1) leaves C as it
// is in both spaces; a coloured light acts as the grey of its luma.
TEST(LumaOnly, UnlitIdentityAndColouredLightsAsTheirLuma) {
  for (LumaSpace s : {LumaSpace::Yiq, LumaSpace::CieLstar}) {
    Shader<double> one(material(Lambert{}, s), {AmbientLight{dvec3(1.0)}});
    for (dvec3 c : kColours) {
      const dvec3 f = one.shade(kP, kN, kV, c);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(f[k], c[k], 1e-12) << toString(s);
    }
    const dvec3 red(1.0, 0.1, 0.1);
    const double y = luma_only::lightLuma(s, red);
    Shader<double> coloured(material(WrapAround{}, s), {PointLight{lightAt(50), red, {}}});
    Shader<double> grey(material(WrapAround{}, s), {PointLight{lightAt(50), dvec3(y), {}}});
    const dvec3 c = kColours[1];
    const dvec3 a = coloured.shade(kP, kN, kV, c), b = grey.shade(kP, kN, kV, c);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 1e-12) << toString(s);
  }
}

// The fast path (float) computes the mode as the reference (double) does.
TEST(LumaOnly, FloatMatchesDouble) {
  const std::vector<Light> lights = {PointLight{lightAt(30), dvec3(1.0, 0.9, 0.8), {}}, AmbientLight{dvec3(0.1)}};
  for (LumaSpace s : {LumaSpace::Yiq, LumaSpace::CieLstar}) {
    Shader<double> d(material(ClassicPhong{}, s), lights);
    Shader<float> f(material(ClassicPhong{}, s), lights);
    for (double deg : kAngles)
      for (dvec3 c : kColours) {
        const glm::dvec3 n = glm::normalize(lightAt(deg));
        const dvec3 a = d.shade(kP, n, kV, c);
        const dvec3 b(f.shade(glm::vec3(kP), glm::vec3(n), glm::vec3(kV), glm::vec3(c)));
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], 2e-6) << toString(s) << " " << deg;
      }
  }
}

// The CIE L* space: white is L* 100 with a* = b* = 0; L* of Y/Yn.
TEST(LumaOnly, CieWhitePointAndLightness) {
  const dvec3 w = lab(dvec3(1.0));
  EXPECT_NEAR(w.x, 100.0, 1e-12);
  EXPECT_NEAR(w.y, 0.0, 1e-12);
  EXPECT_NEAR(w.z, 0.0, 1e-12);
  EXPECT_NEAR(colour::lightness(0.18), 49.496, 1e-3);  // 18% grey: L* ~ 49.5
  EXPECT_NEAR(colour::labFInverse(colour::labF(0.001)), 0.001, 1e-15);  // the linear segment
  const dvec3 c(0.3, 0.6, 0.2);
  const dvec3 back = colour::rgbOfRelativeXyz(colour::relativeXyz(c));
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(back[k], c[k], 1e-15);
}

TEST(LumaOnly, SceneFieldParsesWritesAndRejectsOtherValues) {
  const std::string scene = R"({
  "format": "xval-scene/1", "name": "t",
  "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 64, "height": 48},
  "objects": [{"shape": "sphere"}],
  "material": {"model": {"type": "lambert"}, "luma_only": VALUE},
  "lights": [{"type": "point", "position": [1, 2, 3]}]
})";
  auto with = [&](const std::string& v) {
    std::string t = scene;
    t.replace(t.find("VALUE"), 5, v);
    return t;
  };
  const Scene a = parseScene(with("\"cie_lstar\""), "dir/scene.json");
  ASSERT_TRUE(a.material.luma_only.has_value());
  EXPECT_EQ(*a.material.luma_only, LumaSpace::CieLstar);
  EXPECT_EQ(*parseScene(with("\"yiq\""), "dir/scene.json").material.luma_only, LumaSpace::Yiq);
  const std::string written = sceneToJson(a).dump();
  EXPECT_NE(written.find("\"luma_only\":\"cie_lstar\""), std::string::npos) << written;
  for (const std::string bad : {"\"yuv\"", "1", "true"}) {
    try {
      parseScene(with(bad), "dir/scene.json");
      ADD_FAILURE() << "no error for " << bad;
    } catch (const SceneError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("dir/scene.json"), std::string::npos) << m;
      EXPECT_NE(m.find("material.luma_only"), std::string::npos) << m;
      if (bad == "\"yuv\"") {
        EXPECT_NE(m.find("yuv"), std::string::npos) << m;
        EXPECT_NE(m.find("cie_lstar"), std::string::npos) << m;
      }
    }
  }
  // The precision bound carries the mode's factor (precision_limits.h M).
  Scene off = a;
  off.material.luma_only.reset();
  EXPECT_DOUBLE_EQ(shadingBound(a), 64.0 * shadingBound(off));
}

// docs/models.md: YUV's luma-only mode gives YIQ's up to the luma rows'
// rounding. Both YIQ->RGB and YUV->RGB have first column (1,1,1) and I, Q
// are a rotation of scaled U, V, so keeping one pair keeps the other; the
// only difference is Y_C's row: the listing's (0.29889531, 0.58662247,
// 0.11448223) against Rec. 601's (0.299, 0.587, 0.114). With the model lit
// in grey Y_out = K Y_C + S, F - C = (K - 1) Y_C + S, so the two differ by
// |K - 1| |dRow . C|. Measured over a grid of colours and K in [0, 2]:
TEST(LumaOnly, YuvDiffersFromYiqOnlyByTheLumaRowsRounding) {
  const double yuv[3] = {0.299, 0.587, 0.114};
  double worst = 0.0;
  dvec3 at(0);
  double at_k = 0;
  const int n = 16;
  for (int r = 0; r <= n; ++r)
    for (int g = 0; g <= n; ++g)
      for (int b = 0; b <= n; ++b)
        for (int k = 0; k <= 8; ++k) {
          const dvec3 c(r / double(n), g / double(n), b / double(n));
          const double kk = k / 4.0, s = 0.25;
          const double y_yiq = colour::luma(c), y_yuv = yuv[0] * c.x + yuv[1] * c.y + yuv[2] * c.z;
          const dvec3 f_yiq = c + dvec3(kk * y_yiq + s - y_yiq), f_yuv = c + dvec3(kk * y_yuv + s - y_yuv);
          const double d = std::abs(f_yiq.x - f_yuv.x);
          if (d > worst) worst = d, at = c, at_k = kk;
        }
  std::printf("largest |F_yiq - F_yuv| = %.3g (%.1f/65535, %.3f/255) at C = (%g, %g, %g), K = %g\n", worst,
              worst * 65535, worst * 255, at.x, at.y, at.z, at_k);
  // The bound: |K - 1| <= 1 times the larger of the positive and negative
  // parts of the rows' difference (a colour in [0,1]^3 picks one of them).
  double pos = 0, neg = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = colour::kRgbToYiq[0][k] - yuv[k];
    (d > 0 ? pos : neg) += std::abs(d);
  }
  EXPECT_NEAR(worst, std::max(pos, neg), 1e-12);
  EXPECT_LT(worst, 5e-4);
}
