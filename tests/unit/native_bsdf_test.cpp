// The native tiers' conversions (blender/native_bsdf.h): the Roughness
// sockets and the pass weights, checked by the whole chain written out from
// Cycles' source (a RAW-imported point light of power I watts delivers
// I / (4 pi) x eval / d^2 into DiffDir / GlossDir; eval as in
// unit/cycles_closures.h) against our models' per-light value
// I / d^2 (kd O + ks S); and the scenes the tier refuses, with the reason.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "blender/native_bsdf.h"
#include "shading/models.h"
#include "unit/cycles_closures.h"

namespace {

using namespace xval;
using glm::dvec3;
constexpr double kPi = std::numbers::pi;

Scene sceneWith(LightingModel model) {
  Scene s;
  s.name = "native_test";
  s.material.model = model;
  s.material.base_color = dvec3(1.0);
  PointLight p;
  p.position = dvec3(1, 2, 3);
  p.color = dvec3(5.0);
  p.attenuation = {1e-9, 0.0, 1.0};
  s.lights = {p};
  return s;
}

CookTorrance cyclesSet(models::MicrofacetD d, double alpha, double kd, double ks) {
  CookTorrance c;
  c.distribution = d, c.geometry = models::MicrofacetG::Smith, c.fresnel = models::MicrofacetF::None;
  c.roughness = alpha, c.kd = kd, c.ks = ks;
  return c;
}

// Random unit N, L, V with N.L > 0 and N.V > 0 (where both models are
// non-zero), as the tier meets them on a lit, visible surface.
struct Dirs {
  dvec3 n, l, v;
};
std::vector<Dirs> randomDirs() {
  std::mt19937 rng(33);
  std::normal_distribution<double> g;
  auto unit = [&] { return glm::normalize(dvec3(g(rng), g(rng), g(rng))); };
  std::vector<Dirs> out;
  while (out.size() < 2000) {
    Dirs d{unit(), unit(), unit()};
    if (glm::dot(d.n, d.l) > 0.02 && glm::dot(d.n, d.v) > 0.02) out.push_back(d);
  }
  return out;
}

// What the harness's passes hold per unit of I / d^2 (the light's
// I / (4 pi) times Cycles' eval of the nodes the tier asks for), weighted
// by the tier: what blender-native compares with the reference.
double nativeValue(const NativeBsdf& n, const Dirs& d) {
  const double diffdir = test::cyclesOrenNayarEval(n.diffuse_roughness, d.n, d.l, d.v) / (4.0 * kPi);
  double glossdir = 0.0;
  if (n.glossy != NativeBsdf::Glossy::None) {
    const double alpha = n.glossy_roughness * n.glossy_roughness;  // Cycles squares the socket
    glossdir = test::cyclesGlossyEval(n.glossy == NativeBsdf::Glossy::Ggx, alpha, d.n, d.l, d.v) / (4.0 * kPi);
  }
  return n.diffuse_weight * diffdir + n.glossy_weight * glossdir;
}

}  // namespace

TEST(NativeBsdf, LambertIsDiffuseRoughnessZeroTimesFourPiSquared) {
  const NativeBsdf n = nativeBsdf(sceneWith(Lambert{}));
  EXPECT_EQ(n.diffuse_roughness, 0.0);
  EXPECT_EQ(n.glossy, NativeBsdf::Glossy::None);
  EXPECT_DOUBLE_EQ(n.diffuse_weight, 4.0 * kPi * kPi);
  for (const Dirs& d : randomDirs())
    ASSERT_NEAR(nativeValue(n, d), models::lambert(glm::dot(d.n, d.l)), 1e-12);
}

TEST(NativeBsdf, OrenNayarCyclesIsTheDiffuseBsdfWithRoughnessSigma) {
  for (double sigma : {0.0, 0.2, 0.8, 1.0}) {
    for (double kd : {1.0, 0.8}) {
      const NativeBsdf n = nativeBsdf(sceneWith(OrenNayar{OrenNayar::Variant::Cycles, kd, sigma}));
      EXPECT_EQ(n.diffuse_roughness, sigma);
      const auto ab = models::orenNayarCyclesAB(sigma);
      for (const Dirs& d : randomDirs()) {
        const double ours = kd * models::orenNayarCycles(glm::dot(d.n, d.l), glm::dot(d.n, d.v),
                                                         glm::dot(d.l, d.v), ab.a, ab.b);
        ASSERT_NEAR(nativeValue(n, d), ours, 1e-12) << "sigma " << sigma << " kd " << kd;
      }
    }
  }
}

// The finding (docs/blender-export.md, "Native tiers"): with Roughness =
// B/A and the weight kd A (pi + K B/A) 4 pi, Cycles' Diffuse BSDF equals
// the qualitative Oren-Nayar exactly where s = L.V - N.L N.V > 0 and is
// darker by kd B |s| N.L where s < 0 (Cycles keeps the negative s, the
// qualitative model clamps max(0, cos dphi)).
TEST(NativeBsdf, OrenNayarQualitativeAgreesWhereSIsPositiveAndDiffersByBsElsewhere) {
  const double sigma = 0.8, kd = 0.8;
  const NativeBsdf n = nativeBsdf(sceneWith(OrenNayar{OrenNayar::Variant::Qualitative, kd, sigma}));
  const auto q = models::orenNayarQualitativeAB(sigma);
  EXPECT_NEAR(n.diffuse_roughness, q.b / q.a, 1e-15);
  EXPECT_LT(n.diffuse_roughness, 1.0);  // within Cycles' clamp
  int negative = 0;
  for (const Dirs& d : randomDirs()) {
    const double x = glm::dot(d.n, d.l), y = glm::dot(d.n, d.v), lv = glm::dot(d.l, d.v);
    const double ours = kd * models::orenNayarQualitative(x, y, lv, q.a, q.b);
    const double s = lv - x * y;
    const double finding = s < 0 ? kd * q.b * s * x : 0.0;
    ASSERT_NEAR(nativeValue(n, d), ours + finding, 1e-12);
    negative += s < 0;
  }
  EXPECT_GT(negative, 100);  // the difference was exercised
}

TEST(NativeBsdf, CookTorranceCyclesSetIsTheGlossyBsdfWithRoughnessSqrtAlpha) {
  for (auto dist : {models::MicrofacetD::Ggx, models::MicrofacetD::Beckmann}) {
    for (double alpha : {0.04, 0.09, 0.25, 0.5, 1.0}) {
      const CookTorrance c = cyclesSet(dist, alpha, 0.6, 0.3);
      const NativeBsdf n = nativeBsdf(sceneWith(c));
      EXPECT_EQ(n.glossy, dist == models::MicrofacetD::Ggx ? NativeBsdf::Glossy::Ggx : NativeBsdf::Glossy::Beckmann);
      EXPECT_DOUBLE_EQ(n.glossy_roughness, std::sqrt(alpha));
      for (const Dirs& d : randomDirs()) {
        const double ours = c.kd * models::lambert(glm::dot(d.n, d.l)) +
                            c.ks * models::cookTorranceSpecular(d.n, d.l, d.v, c.distribution, c.geometry,
                                                                c.fresnel, c.roughness, c.f0);
        ASSERT_NEAR(nativeValue(n, d), ours, 1e-9 * std::max(1.0, ours)) << "alpha " << alpha;
      }
    }
  }
}

TEST(NativeBsdf, NoSpecularIsNoGlossyBsdf) {
  const NativeBsdf n = nativeBsdf(sceneWith(cyclesSet(models::MicrofacetD::Ggx, 0.25, 0.5, 0.0)));
  EXPECT_EQ(n.glossy, NativeBsdf::Glossy::None);
  EXPECT_EQ(n.glossy_weight, 0.0);
}

// Each refusal names the scene and what the tier needs.
void expectRefusal(const Scene& s, const std::string& reason) {
  try {
    nativeBsdf(s);
    ADD_FAILURE() << "accepted; expected a refusal mentioning: " << reason;
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("native_test"), std::string::npos) << what;
    EXPECT_NE(what.find(reason), std::string::npos) << what;
  }
}

TEST(NativeBsdf, RefusesWhatNoBuiltInBsdfComputes) {
  Scene textured = sceneWith(Lambert{});
  textured.material.texture = TextureSpec{};
  expectRefusal(textured, "untextured white material");
  Scene coloured = sceneWith(Lambert{});
  coloured.material.base_color = dvec3(1.0, 0.5, 0.5);
  expectRefusal(coloured, "untextured white material");
  Scene two = sceneWith(Lambert{});
  two.lights.push_back(two.lights[0]);
  expectRefusal(two, "exactly one light, a point light");
  Scene ambient = sceneWith(Lambert{});
  ambient.lights.push_back(AmbientLight{});
  expectRefusal(ambient, "no ambient");
  Scene directional = sceneWith(Lambert{});
  directional.lights = {DirectionalLight{}};
  expectRefusal(directional, "a point light");
  Scene red = sceneWith(Lambert{});
  std::get<PointLight>(red.lights[0]).color = dvec3(1, 0, 0);
  expectRefusal(red, "white light");
  Scene linear = sceneWith(Lambert{});
  std::get<PointLight>(linear.lights[0]).attenuation = {0.0, 1.0, 0.0};
  expectRefusal(linear, "inverse square");
  Scene flat = sceneWith(Lambert{});
  flat.shading = ShadingMode::Flat;
  expectRefusal(flat, "smooth (phong) shading");
  expectRefusal(sceneWith(Lambert{dvec3(0.5)}), "lambert c0 = [1,1,1]");
  expectRefusal(sceneWith(OrenNayar{OrenNayar::Variant::Cycles, 1.0, 1.5}), "clamps the Diffuse BSDF's Roughness");
  CookTorrance paper = cyclesSet(models::MicrofacetD::Beckmann, 0.3, 0.5, 0.5);
  paper.geometry = models::MicrofacetG::VGroove;
  expectRefusal(sceneWith(paper), "geometry cook_torrance");
  CookTorrance schlick = cyclesSet(models::MicrofacetD::Ggx, 0.3, 0.5, 0.5);
  schlick.fresnel = models::MicrofacetF::Schlick;
  expectRefusal(sceneWith(schlick), "fresnel schlick");
  expectRefusal(sceneWith(cyclesSet(models::MicrofacetD::Ggx, 1e-4, 0.5, 0.5)), "no highlight");
  expectRefusal(sceneWith(ClassicPhong{}), "no built-in BSDF for the scene's model");
}

TEST(NativeBsdf, CombineWeighsBothPassesAndSaturates) {
  NativeBsdf n;
  n.diffuse_weight = 2.0, n.glossy_weight = 10.0;
  Image d(2, 1, false), g(2, 1, false);
  d.rgba = {0.1f, 0.2f, 0.3f, 1.0f, 0.4f, 0.0f, 0.0f, 0.5f};
  g.rgba = {0.01f, 0.0f, 0.02f, 1.0f, 0.1f, -1.0f, 0.0f, 0.5f};
  const Image out = combineNativePasses(n, d, g);
  const std::vector<float> want = {0.3f, 0.4f, 0.8f, 1.0f, 1.0f, 0.0f, 0.0f, 0.5f};
  for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(out.rgba[i], want[i], 1e-6f) << i;
  EXPECT_THROW(combineNativePasses(n, d, Image(1, 1, false)), std::invalid_argument);
}

// EEVEE renders the combined image: the BSDFs' grey colours carry the
// weights relative to the larger one, which scales the image back.
TEST(NativeBsdf, EeveeColoursCarryTheWeightsBelowOne) {
  const NativeBsdf n = nativeBsdf(sceneWith(cyclesSet(models::MicrofacetD::Ggx, 0.25, 0.5, 0.1)));
  const NativeColours c = eeveeColours(n);
  EXPECT_DOUBLE_EQ(c.scale, n.diffuse_weight);
  EXPECT_DOUBLE_EQ(c.diffuse, 1.0);
  EXPECT_DOUBLE_EQ(c.glossy * c.scale, n.glossy_weight);
  EXPECT_DOUBLE_EQ(c.glossy, 0.2);
  const NativeColours black = eeveeColours(nativeBsdf(sceneWith(cyclesSet(models::MicrofacetD::Ggx, 0.25, 0.0, 0.0))));
  EXPECT_EQ(black.diffuse, 0.0);
  EXPECT_EQ(black.glossy, 0.0);
  Image combined(1, 1, false);
  combined.rgba = {0.01f, 0.02f, 0.5f, 1.0f};
  const Image out = scaleNativeCombined(10.0, combined);
  EXPECT_NEAR(out.rgba[0], 0.1f, 1e-6f);
  EXPECT_NEAR(out.rgba[1], 0.2f, 1e-6f);
  EXPECT_EQ(out.rgba[2], 1.0f);
  EXPECT_EQ(out.rgba[3], 1.0f);
}
