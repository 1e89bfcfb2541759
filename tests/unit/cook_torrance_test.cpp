// cook_torrance (shading/model/cook_torrance.h, models::cookTorranceSpecular):
// its limits and identities, its two named parameter sets (Cycles' Glossy
// BSDF, Cook & Torrance 1982) against formulas written out here, D's
// normalisation, and the numerics at grazing angles and small roughness.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "shading/model/cook_torrance.h"
#include "shading/shader.h"
#include "unit/cycles_closures.h"

namespace {

using namespace xval;
using models::MicrofacetD;
using models::MicrofacetF;
using models::MicrofacetG;
using glm::dvec3;
constexpr double kPi = std::numbers::pi;

dvec3 dir(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

double spec(const CookTorrance& m, dvec3 n, dvec3 l, dvec3 v) {
  return models::cookTorranceSpecular(n, l, v, m.distribution, m.geometry, m.fresnel, m.roughness, m.f0);
}

CookTorrance cycles(MicrofacetD d, double alpha) {
  CookTorrance m;
  m.distribution = d, m.geometry = MicrofacetG::Smith, m.fresnel = MicrofacetF::None, m.roughness = alpha;
  return m;
}

// Hand-computed: N = L = V: H = N, tan = 0, D = 1 / (pi alpha^2), G = 1,
// S = pi D / 4 = 1 / (4 alpha^2) (both distributions): 4 at alpha 1/4.
// L, V at 60 degrees either side of N in one plane: H = N again,
// D = 1 / (pi alpha^2); GGX G1(1/2) = 2 / (1 + sqrt(1 + alpha^2 tan^2 60))
// = 2 / (1 + sqrt(1 + 3/16)) = 2 / 2.0897247 = 0.9570638 at alpha 1/4,
// G = G1^2; S = pi D G / (4 N.V) = G / (2 alpha^2) = 8 G = 7.3277697.
// Beckmann at 60 degrees: a = 1 / (alpha tan 60) = 4 / sqrt 3 = 2.309 >= 1.6:
// G1 = 1, S = 1 / (2 alpha^2) = 8.
TEST(CookTorrance, TheCyclesSetAtHandComputedAngles) {
  const dvec3 n(0, 0, 1);
  for (MicrofacetD d : {MicrofacetD::Ggx, MicrofacetD::Beckmann})
    EXPECT_NEAR(spec(cycles(d, 0.25), n, n, n), 4.0, 1e-12);
  const dvec3 l = dir(kPi / 3, 0), v = dir(kPi / 3, kPi);
  EXPECT_NEAR(spec(cycles(MicrofacetD::Ggx, 0.25), n, l, v), 7.3277697, 1e-6);
  EXPECT_NEAR(spec(cycles(MicrofacetD::Beckmann, 0.25), n, l, v), 8.0, 1e-12);
}

// Cycles 3.4's Glossy eval as written there (unit/cycles_closures.h),
// times pi (a point light of power 4 pi^2 Lc: docs/models.md) at random
// angles.
using test::cyclesGlossyEval;

TEST(CookTorrance, TheCyclesSetIsCyclesGlossyTimesPi) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  const dvec3 n(0, 0, 1);
  for (int i = 0; i < 2000; ++i) {
    const double alpha = 0.05 + 0.95 * u(rng);
    const dvec3 l = dir(std::acos(u(rng)), 2 * kPi * u(rng)), v = dir(std::acos(u(rng)), 2 * kPi * u(rng));
    for (bool ggx : {true, false}) {
      const double want = kPi * cyclesGlossyEval(ggx, alpha, n, l, v);
      const double got = spec(cycles(ggx ? MicrofacetD::Ggx : MicrofacetD::Beckmann, alpha), n, l, v);
      EXPECT_NEAR(got, want, 1e-9 * std::max(1.0, want)) << "alpha " << alpha << " ggx " << ggx;
    }
  }
}

// The paper: R_s = (F / pi) D G / ((N.L)(N.V)), D = exp(-(tan b / m)^2) /
// (m^2 cos^4 b), G = min(1, 2 nh nv / vh, 2 nh nl / vh); in our units
// pi R_s N.L: the set beckmann, cook_torrance, roughness m, ks = 4.
TEST(CookTorrance, ThePaperSetIsThePapersFormula) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(0, 1);
  const dvec3 n(0, 0, 1);
  for (int i = 0; i < 2000; ++i) {
    CookTorrance m;
    m.distribution = MicrofacetD::Beckmann, m.geometry = MicrofacetG::VGroove, m.fresnel = MicrofacetF::Schlick;
    m.roughness = 0.05 + 0.95 * u(rng), m.f0 = u(rng), m.ks = 4;
    const dvec3 l = dir(std::acos(u(rng)), 2 * kPi * u(rng)), v = dir(std::acos(u(rng)), 2 * kPi * u(rng));
    const double nl = glm::dot(n, l), nv = glm::dot(n, v);
    const dvec3 h = glm::normalize(l + v);
    const double nh = glm::dot(n, h), vh = glm::dot(v, h), b = std::acos(nh), mm = m.roughness;
    if (vh < 1.0 / 1024) continue;  // where the model departs from the paper (models.h)
    const double D = std::exp(-std::pow(std::tan(b) / mm, 2)) / (mm * mm * std::pow(std::cos(b), 4));
    const double G = std::min({1.0, 2 * nh * nv / vh, 2 * nh * nl / vh});
    const double F = m.f0 + (1 - m.f0) * std::pow(1 - vh, 5);
    const double Rs = F / kPi * D * G / (nl * nv);
    const double want = kPi * Rs * nl;
    EXPECT_NEAR(m.ks * spec(m, n, l, v), want, 1e-9 * std::max(1.0, want));
  }
}

// ks = 0 is Lambert: the shader's colour equals lambert's with c0 = kd.
TEST(CookTorrance, KsZeroIsLambert) {
  Material ct, lam;
  CookTorrance m;
  m.ks = 0, m.kd = 0.7;
  ct.model = m;
  lam.model = Lambert{dvec3(0.7)};
  const std::vector<Light> lights{PointLight{dvec3(1, 2, 3), dvec3(0.9, 0.8, 0.7), Attenuation{}}, AmbientLight{dvec3(0.1)}};
  const Shader<double> a(ct, lights), b(lam, lights);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 200; ++i) {
    const dvec3 p(u(rng), u(rng), u(rng)), nn = glm::normalize(dvec3(u(rng), u(rng), u(rng)));
    const dvec3 v = glm::normalize(dvec3(u(rng), u(rng), 1.5));
    const dvec3 c(0.5, 0.6, 0.7);
    const dvec3 x = a.shade(p, nn, v, c), y = b.shade(p, nn, v, c);
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(x[k], y[k]);
  }
}

// The integral of D (N.H) over the hemisphere of H is 1 (both D), by the
// midpoint rule in theta: 2 pi int_0^{pi/2} D cos sin dtheta.
TEST(CookTorrance, BothDistributionsAreNormalised) {
  for (MicrofacetD d : {MicrofacetD::Ggx, MicrofacetD::Beckmann})
    for (double alpha : {0.05, 0.25, 0.6, 1.0}) {
      const int steps = 400000;
      const double dt = kPi / 2 / steps;
      double sum = 0;
      for (int i = 0; i < steps; ++i) {
        const double t = (i + 0.5) * dt, c = std::cos(t), s = std::sin(t);
        sum += models::microfacetD(d, c, s * s, alpha) * c * s;
      }
      EXPECT_NEAR(2 * kPi * sum * dt, 1.0, 1e-6) << "alpha " << alpha << " ggx " << (d == MicrofacetD::Ggx);
    }
}

// Smith's G1 is 1 at normal incidence and falls to 0 at grazing; G1(x) / x
// stays finite (2 / alpha for GGX, 3.535 / alpha for Beckmann's
// approximation) as x -> 0.
TEST(CookTorrance, SmithG1IsOneAtNormalIncidenceAndFiniteOverCosAtGrazing) {
  for (MicrofacetD d : {MicrofacetD::Ggx, MicrofacetD::Beckmann})
    for (double alpha : {0.01, 0.3, 1.0}) {
      EXPECT_DOUBLE_EQ(models::smithG1OverCos(d, 1.0, 0.0, alpha), 1.0);
      const double x = 1e-300;
      const double g = models::smithG1OverCos(d, x, 1.0, alpha);
      EXPECT_TRUE(std::isfinite(g));
      EXPECT_LE(g, (d == MicrofacetD::Ggx ? 2.0 : 3.535) / alpha * (1 + 1e-12));
    }
  EXPECT_NEAR(models::smithG1OverCos(MicrofacetD::Ggx, 0.0, 1.0, 0.5), 4.0, 1e-15);
}

// At grazing N.V (1e-30) S is finite and continuous (the 1 / N.V is formed
// as G / N.V); the V-groove's peak at L -> -V, both grazing, stays within the
// bound the precision limits use (specularGain).
TEST(CookTorrance, GrazingAnglesStayFiniteAndWithinTheBound) {
  const dvec3 n(0, 0, 1);
  for (MicrofacetD d : {MicrofacetD::Ggx, MicrofacetD::Beckmann})
    for (MicrofacetG g : {MicrofacetG::Smith, MicrofacetG::VGroove}) {
      CookTorrance m = cycles(d, 0.3);
      m.geometry = g;
      const dvec3 l = dir(1.2, 0);
      const double s1 = spec(m, n, l, dir(kPi / 2 - 1e-30, kPi)), s2 = spec(m, n, l, dir(kPi / 2 - 1e-8, kPi));
      EXPECT_TRUE(std::isfinite(s1));
      EXPECT_NEAR(s1, s2, 1e-6 * std::max(1.0, s2));
      // L nearly -V, both grazing.
      const double e = 1e-9;
      const double retro = spec(m, n, dir(kPi / 2 - 2 * e, 0.0), dir(kPi / 2 - e, kPi + 1e-7));
      EXPECT_TRUE(std::isfinite(retro));
      EXPECT_LE(retro, m.specularGain());
    }
}

// specularGain bounds S at random geometries and roughness (and is reached
// within a factor of 100: not a vacuous bound).
TEST(CookTorrance, SpecularGainBoundsTheSpecularTerm) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0, 1);
  const dvec3 n(0, 0, 1);
  for (MicrofacetD d : {MicrofacetD::Ggx, MicrofacetD::Beckmann})
    for (MicrofacetG g : {MicrofacetG::Smith, MicrofacetG::VGroove})
      for (double alpha : {0.02, 0.2, 0.7, 1.0}) {
        CookTorrance m = cycles(d, alpha);
        m.geometry = g;
        double top = 0;
        for (int i = 0; i < 20000; ++i) {
          const double tl = std::acos(u(rng)), tv = std::acos(std::pow(u(rng), 4));
          const dvec3 l = dir(tl, 2 * kPi * u(rng)), v = dir(tv, 2 * kPi * u(rng));
          top = std::max(top, spec(m, n, l, v));
        }
        top = std::max(top, spec(m, n, n, n));
        EXPECT_LE(top, m.specularGain()) << alpha;
        if (g == MicrofacetG::Smith) {
          EXPECT_GE(100 * top, m.specularGain()) << alpha;
        }
      }
}

// In float, near the centre of a narrow highlight (alpha 0.01), S agrees
// with double to 1e-4: tan^2 comes from |N x H|^2, not from 1 - (N.H)^2,
// whose cancellation gives ~1e-3 here.
TEST(CookTorrance, FloatKeepsANarrowHighlightsPrecision) {
  const glm::vec3 nf(0, 0, 1);
  for (MicrofacetD d : {MicrofacetD::Ggx, MicrofacetD::Beckmann})
    for (double off : {0.003, 0.007, 0.012, 0.02}) {
      const dvec3 l = dir(0.4 + off, 0.3), v = dir(0.4, 0.3 + kPi);
      const double want = models::cookTorranceSpecular(dvec3(nf), dvec3(glm::vec3(l)), dvec3(glm::vec3(v)), d,
                                                        MicrofacetG::Smith, MicrofacetF::None, 0.01, 0.0);
      const float got = models::cookTorranceSpecular(nf, glm::vec3(l), glm::vec3(v), d, MicrofacetG::Smith,
                                                     MicrofacetF::None, 0.01f, 0.0f);
      EXPECT_NEAR(got, want, 1e-4 * want + 1e-30) << off;
    }
}

}  // namespace
