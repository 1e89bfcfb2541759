// The shader (model + lights) against hand-computed values.
#include <gtest/gtest.h>

#include "shading/shader.h"

using namespace xval;
using glm::dvec3;

namespace {
void expectNear(dvec3 a, dvec3 b, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}
const dvec3 kC(0.5, 0.25, 0.1);
const dvec3 kN(0, 0, 1), kEyeDir(0, 0, 1), kOrigin(0);
const double kS = 0.70710678118654752;

Material material(LightingModel m) {
  Material mat;
  mat.model = m;
  return mat;
}
std::vector<Light> pointAndAmbient(dvec3 pos) {
  return {PointLight{pos, dvec3(1.0), {}}, AmbientLight{dvec3(0.1)}};
}
}  // namespace

TEST(Shader, ClassicPhongPaperHeadOn) {
  Shader<double> sh(material(ClassicPhong{}), pointAndAmbient({0, 0, 2}));
  // F = C (0.1 + 1) + 1
  expectNear(sh.shade(kOrigin, kN, kEyeDir, kC), dvec3(1.55, 1.275, 1.11), 1e-12);
}

TEST(Shader, ClassicPhongPaperAt45Degrees) {
  ClassicPhong p;
  p.shininess = 2.0;
  Shader<double> sh(material(p), pointAndAmbient({1, 0, 1}));
  // N.L = s, R.V = s, S = 0.5: F = C (0.1 + s) + 0.5
  expectNear(sh.shade(kOrigin, kN, kEyeDir, kC),
             dvec3(0.9035533905932738, 0.7017766952966369, 0.5807106781186547), 1e-12);
}

// The listing does not gate the highlight by N.L: a light below the surface
// still adds a highlight where R.V > 0.
TEST(Shader, ClassicPhongHighlightIsNotGatedByNdotL) {
  Shader<double> sh(material(ClassicPhong{}), pointAndAmbient({1, 0, -1}));
  dvec3 v = glm::normalize(dvec3(-1, 0, -1));  // exactly along R
  expectNear(sh.shade(kOrigin, kN, v, kC), kC * 0.1 + dvec3(1.0), 1e-12);
}

TEST(Shader, ClassicPhongCourseVariantTintsSpecularAndKeepsAmbientOutsideSpot) {
  ClassicPhong p;
  p.variant = ClassicPhong::Variant::Course;
  p.ka = 0.2, p.kd = 0.5, p.ks = 0.25;
  SpotLight spot;
  spot.position = {0, 0, 2};
  spot.direction = {0, 0, -1};
  spot.cutoff_deg = 10;
  spot.attenuation = {1.0, 0.5, 0.0};  // d = 2: att = 1/2
  Shader<double> sh(material(p), {spot});
  // Inside: att (ka + kd + ks) (Lc x C) = 0.5 * 0.95 * C
  expectNear(sh.shade(kOrigin, kN, kEyeDir, kC), kC * 0.475, 1e-12);
  // Outside the cone (point at x = 1: angle 26.6 deg > 10): att ka C,
  // att = 1/(1 + 0.5 sqrt(5)).
  double att = 1.0 / (1.0 + 0.5 * std::sqrt(5.0));
  expectNear(sh.shade({1, 0, 0}, kN, kEyeDir, kC), kC * (0.2 * att), 1e-12);
}

TEST(Shader, YiqLumaHeadOn) {
  Shader<double> sh(material(YiqLuma{}), pointAndAmbient({0, 0, 2}));
  expectNear(sh.shade(kOrigin, kN, kEyeDir, kC), dvec3(1.4, 1.15, 1.0), 1e-12);
}

TEST(Shader, YiqLumaAt45Degrees) {
  YiqLuma y;
  y.shininess = 2.0;
  Shader<double> sh(material(y), pointAndAmbient({1, 0, 1}));
  expectNear(sh.shade(kOrigin, kN, kEyeDir, kC),
             dvec3(0.8406754020821139, 0.5906754020821139, 0.44067540208211387), 1e-12);
}

TEST(Shader, PointLightAttenuation) {
  Lambert l{dvec3(1.0)};
  PointLight pl{{0, 0, 2}, dvec3(1.0), {0.5, 0.25, 0.125}};  // d = 2: 1/(0.5+0.5+0.5)
  Shader<double> sh(material(l), {pl});
  expectNear(sh.shade(kOrigin, kN, kEyeDir, kC), kC * (1.0 / 1.5), 1e-12);
}

TEST(Shader, DirectionalLightUsesMinusDirection) {
  Shader<double> sh(material(Lambert{dvec3(1.0)}),
                    {DirectionalLight{glm::normalize(dvec3(-1, 0, -1)), dvec3(1.0)}});
  expectNear(sh.shade({5, 5, 5}, kN, kEyeDir, kC), kC * kS, 1e-12);
}

TEST(Shader, SeveralLightsSum) {
  Shader<double> sh(material(Lambert{dvec3(1.0)}),
                    {DirectionalLight{{0, 0, -1}, dvec3(0.25)},
                     DirectionalLight{glm::normalize(dvec3(1, 0, -1)), dvec3(1.0)},
                     AmbientLight{dvec3(0.05)}});
  expectNear(sh.shade(kOrigin, kN, kEyeDir, dvec3(1.0)), dvec3(0.25 + kS + 0.05), 1e-12);
}

TEST(Shader, LightAtTheSurfacePointGivesNoNan) {
  Shader<double> sh(material(ClassicPhong{}), pointAndAmbient({0, 0, 0}));
  dvec3 c = sh.shade(kOrigin, kN, kEyeDir, kC);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(std::isfinite(c[i]));
  expectNear(c, kC * 0.1, 1e-15);  // ambient only; no direction to the light
}

TEST(Shader, SpecularTermSkippedWhenWeightIsZero) {
  ClassicPhong p;
  p.ks = 0.0;
  EXPECT_FALSE(Shader<double>(material(p), {}).usesSpecular());
  EXPECT_TRUE(Shader<double>(material(ClassicPhong{}), {}).usesSpecular());
  YiqLuma y;
  y.ks = 0.0;
  EXPECT_FALSE(Shader<double>(material(y), {}).usesSpecular());
}

TEST(Shader, AttenuationPreparedOnlyWhenNotNone) {
  Shader<double> sh(material(Lambert{}),
                    {PointLight{{0, 0, 1}, dvec3(1.0), {}},
                     PointLight{{0, 0, 1}, dvec3(1.0), {1.0, 0.1, 0.0}}});
  ASSERT_EQ(sh.lights().size(), 2u);
  EXPECT_FALSE(sh.lights()[0].has_attenuation);
  EXPECT_TRUE(sh.lights()[1].has_attenuation);
}

TEST(Shader, FloatMatchesDouble) {
  Shader<double> d(material(YiqLuma{}), pointAndAmbient({-0.5, 2.0, 1.25}));
  Shader<float> f(material(YiqLuma{}), pointAndAmbient({-0.5, 2.0, 1.25}));
  glm::dvec3 n = glm::normalize(dvec3(0.3, 0.8, 0.5));
  dvec3 a = d.shade(dvec3(0.1, 0.2, 0.3), n, kEyeDir, kC);
  glm::vec3 b = f.shade(glm::vec3(0.1f, 0.2f, 0.3f), glm::vec3(n), glm::vec3(kEyeDir), glm::vec3(kC));
  expectNear(a, dvec3(b), 1e-5);
}
