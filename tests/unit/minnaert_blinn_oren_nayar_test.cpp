// Issue #33's models (minnaert, blinn_phong, oren_nayar): their identities
// with Lambert, the vector forms against the papers' angle forms, and
// hand-computed values (docs/models.md).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "scene/scene.h"
#include "shading/models.h"
#include "shading/shader.h"

namespace m = xval::models;
using glm::dvec3;

namespace {

dvec3 randomUnit(std::mt19937_64& g) {
  std::normal_distribution<double> n;
  dvec3 v;
  do v = dvec3(n(g), n(g), n(g));
  while (glm::length(v) < 1e-3);
  return glm::normalize(v);
}

// A unit vector at polar angle theta from +z, azimuth phi.
dvec3 polar(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

}  // namespace

// Oren-Nayar with sigma 0 (either variant) and Minnaert with k = 1 are
// Lambert's clamp(N.L), bit for bit, wherever N, L, V point (N.V < 0 too).
TEST(IssueModels, SigmaZeroOrenNayarAndMinnaertKOneAreLambert) {
  std::mt19937_64 g(33);
  const auto q = m::orenNayarQualitativeAB(0.0);
  const auto c = m::orenNayarCyclesAB(0.0);
  EXPECT_EQ(q.a, 1.0);
  EXPECT_EQ(q.b, 0.0);
  EXPECT_EQ(c.a, 1.0);
  EXPECT_EQ(c.b, 0.0);
  for (int k = 0; k < 20000; ++k) {
    const dvec3 n = randomUnit(g), l = randomUnit(g), v = randomUnit(g);
    const double x = glm::dot(n, l), y = glm::dot(n, v), lv = glm::dot(l, v);
    EXPECT_EQ(m::orenNayarQualitative(x, y, lv, q.a, q.b), m::lambert(x)) << x << " " << y << " " << lv;
    EXPECT_EQ(m::orenNayarCycles(x, y, lv, c.a, c.b), m::lambert(x)) << x << " " << y << " " << lv;
    EXPECT_EQ(m::minnaert(x, y, 1.0), m::lambert(x)) << x << " " << y;
  }
}

// The same through Shader (lights, attenuation, ambient, colour): the
// models with those parameters shade as lambert with c0 = (1,1,1).
TEST(IssueModels, ShaderOfTheIdentitiesEqualsLambert) {
  using namespace xval;
  const std::vector<Light> lights{AmbientLight{dvec3(0.1, 0.05, 0.0)},
                                  PointLight{dvec3(2, 3, 4), dvec3(0.9, 0.8, 0.7), Attenuation{1.0, 0.1, 0.02}},
                                  DirectionalLight{dvec3(-1, -0.5, -0.2), dvec3(0.3, 0.4, 0.5)}};
  const Shader<double> lambert(Material{Lambert{dvec3(1.0)}, {}, dvec3(1.0)}, lights);
  const Shader<double> q(Material{OrenNayar{OrenNayar::Variant::Qualitative, 1.0, 0.0}, {}, dvec3(1.0)}, lights);
  const Shader<double> c(Material{OrenNayar{OrenNayar::Variant::Cycles, 1.0, 0.0}, {}, dvec3(1.0)}, lights);
  const Shader<double> mi(Material{Minnaert{1.0, 1.0}, {}, dvec3(1.0)}, lights);
  std::mt19937_64 g(7);
  for (int k = 0; k < 2000; ++k) {
    const dvec3 p = randomUnit(g), n = randomUnit(g), v = randomUnit(g), col(0.8, 0.6, 0.4);
    const dvec3 want = lambert.shade(p, n, v, col);
    for (const Shader<double>* s : {&q, &c, &mi}) {
      const dvec3 got = s->shade(p, n, v, col);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], want[i], 1e-15) << "channel " << i;
    }
  }
}

// The vector forms against Oren & Nayar's angle form
//   O = cos(ti) (A + B max(0, cos(phi_i - phi_r)) sin(a) tan(b)),
// a = max(ti, tr), b = min(ti, tr), and Cycles' t = cos(dphi) sin(a) tan(b)
// where it is positive, else sin(ti) sin(tr) cos(dphi).
TEST(IssueModels, OrenNayarVectorFormsEqualTheAngleForms) {
  std::mt19937_64 g(1994);
  std::uniform_real_distribution<double> th(0.0, 1.5), ph(0.0, 2.0 * std::numbers::pi), sg(0.0, 1.2);
  for (int k = 0; k < 20000; ++k) {
    const double ti = th(g), tr = th(g), pi_ = ph(g), pr = ph(g), sigma = sg(g);
    const dvec3 n(0, 0, 1), l = polar(ti, pi_), v = polar(tr, pr);
    const double x = glm::dot(n, l), y = glm::dot(n, v), lv = glm::dot(l, v);
    const double a = std::max(ti, tr), b = std::min(ti, tr), cphi = std::cos(pi_ - pr);
    const double s2 = sigma * sigma;
    const double A = 1.0 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
    const double want_q = std::cos(ti) * (A + B * std::max(0.0, cphi) * std::sin(a) * std::tan(b));
    const auto q = m::orenNayarQualitativeAB(sigma);
    EXPECT_NEAR(m::orenNayarQualitative(x, y, lv, q.a, q.b), want_q, 1e-12) << ti << " " << tr << " " << sigma;
    const double pi = std::numbers::pi;
    const double ca = pi / (pi + (3.0 * pi - 4.0) / 6.0 * sigma), cb = sigma * ca;
    const double t = cphi > 0.0 ? cphi * std::sin(a) * std::tan(b) : std::sin(ti) * std::sin(tr) * cphi;
    const auto c = m::orenNayarCyclesAB(sigma);
    EXPECT_NEAR(m::orenNayarCycles(x, y, lv, c.a, c.b), std::cos(ti) * (ca + cb * t), 1e-12)
        << ti << " " << tr << " " << sigma;
  }
}

// Hand values. Oren-Nayar: ti = 60, tr = 30 degrees, same azimuth, sigma =
// 0.5: A = 1 - 0.125/0.58, B = 0.1125/0.34, sin(60) tan(30) = 1/2, so
// O = (1/2)(A + B/2) = 0.474961967545639. Cycles, same angles, sigma 0.5:
// a = pi / (pi + 0.452064830), b = a / 2, O = (1/2)(a + b/2) = 0.5463...
TEST(IssueModels, OrenNayarHandValues) {
  const double pi = std::numbers::pi;
  const dvec3 n(0, 0, 1), l = polar(pi / 3, 0.0), v = polar(pi / 6, 0.0);
  const double x = glm::dot(n, l), y = glm::dot(n, v), lv = glm::dot(l, v);
  const auto q = m::orenNayarQualitativeAB(0.5);
  EXPECT_NEAR(q.a, 0.784482758620690, 1e-14);
  EXPECT_NEAR(q.b, 0.330882352941176, 1e-14);
  EXPECT_NEAR(m::orenNayarQualitative(x, y, lv, q.a, q.b), 0.5 * (0.784482758620690 + 0.330882352941176 / 2), 1e-14);
  const auto c = m::orenNayarCyclesAB(0.5);
  const double ca = pi / (pi + 0.5 * 0.904129660128230);  // (3 pi - 4) / 6 = 0.904129660128230
  EXPECT_NEAR(c.a, ca, 1e-14);
  EXPECT_NEAR(m::orenNayarCycles(x, y, lv, c.a, c.b), 0.5 * (ca + 0.5 * ca / 2), 1e-14);
  // Opposite azimuths: s < 0. Qualitative: plain A; Cycles keeps the
  // negative s = sin(60) sin(30) cos(180) = -sqrt(3)/4.
  const dvec3 vb = polar(pi / 6, pi);
  const double yb = glm::dot(n, vb), lvb = glm::dot(l, vb);
  EXPECT_NEAR(m::orenNayarQualitative(x, yb, lvb, q.a, q.b), 0.5 * q.a, 1e-14);
  EXPECT_NEAR(m::orenNayarCycles(x, yb, lvb, c.a, c.b), 0.5 * (ca - 0.5 * ca * std::sqrt(3.0) / 4), 1e-14);
}

// Minnaert: x = 0.5, y = 0.8, k = 2: 0.25 x 0.8 = 0.2; k = 0.5: sqrt(0.5) /
// sqrt(0.8); unlit or unseen: 0 (k != 1).
TEST(IssueModels, MinnaertHandValues) {
  EXPECT_NEAR(m::minnaert(0.5, 0.8, 2.0), 0.2, 1e-15);
  EXPECT_NEAR(m::minnaert(0.5, 0.8, 0.5), std::sqrt(0.5) / std::sqrt(0.8), 1e-15);
  EXPECT_EQ(m::minnaert(-0.5, 0.8, 2.0), 0.0);
  EXPECT_EQ(m::minnaert(0.5, -0.1, 2.0), 0.0);
  EXPECT_EQ(m::minnaert(0.5, 0.0, 0.5), 0.0);
  EXPECT_EQ(m::minnaert(0.5, -0.1, 1.0), 0.5);
}

// Blinn-Phong: N = +z, L at 45 degrees, V = N: H at 22.5 degrees, N.H =
// cos(22.5) and N.H^4 = ((2 + sqrt 2) / 4)^2. With C = 0.5, kd = 1, ka = 0,
// ks = 1, a white directional light: F = 0.5 cos(45) + ((2 + sqrt 2)/4)^2.
TEST(IssueModels, BlinnPhongHandValue) {
  using namespace xval;
  const dvec3 n(0, 0, 1), l = glm::normalize(dvec3(1, 0, 1)), v(0, 0, 1);
  const double want_s = std::pow((2.0 + std::sqrt(2.0)) / 4.0, 2.0);
  EXPECT_NEAR(m::phongSpecular(m::halfVector(l, v), n, 4.0), want_s, 1e-15);
  EXPECT_EQ(glm::length(m::halfVector(l, -l)), 0.0);  // L + V = 0: H = 0, no highlight
  EXPECT_EQ(m::phongSpecular(m::halfVector(l, -l), n, 4.0), 0.0);
  const Shader<double> s(Material{BlinnPhong{0.0, 1.0, 1.0, 4.0}, {}, dvec3(0.5)},
                         {DirectionalLight{-l, dvec3(1.0)}});
  const dvec3 got = s.shade(dvec3(0), n, v, dvec3(0.5));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[i], 0.5 * std::sqrt(0.5) + want_s, 1e-15);
}
