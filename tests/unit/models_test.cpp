// The lighting models against hand-computed values, and the identities of
// seed 002 (Forsyth) and of the YIQ reduction (docs/models.md).
#include <gtest/gtest.h>

#include <random>

#include "shading/models.h"

namespace m = xval::models;
using glm::dvec3;

namespace {
void expectNear(dvec3 a, dvec3 b, double tol) {
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << "component " << i;
}
}  // namespace

TEST(Models, ClampAndSaturateMapNanToZero) {
  EXPECT_EQ(m::clamp0(std::nan("")), 0.0);
  EXPECT_EQ(m::saturate(std::nan("")), 0.0);
  EXPECT_EQ(m::saturate(1.5), 1.0);
  EXPECT_EQ(m::saturate(-0.5), 0.0);
  EXPECT_EQ(m::clamp0(2.5), 2.5);
}

TEST(Models, PhongSpecularHandValues) {
  EXPECT_DOUBLE_EQ(m::phongSpecular(0.5, 2.0), 0.25);
  EXPECT_DOUBLE_EQ(m::phongSpecular(-0.5, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(m::phongSpecular(1.0, 55.0), 1.0);
  EXPECT_DOUBLE_EQ(m::phongSpecular(0.3, 0.0), 1.0);  // power 0: constant 1
  // R = 2 (N.L) N - L: L at 45 degrees mirrors to the other side.
  double s = std::sqrt(0.5);
  expectNear(m::reflect(dvec3(0, 0, 1), dvec3(s, 0, s), s), dvec3(-s, 0, s), 1e-15);
}

TEST(Models, ForsythHandValues) {
  const dvec3 c0(1.0, 0.5, 0.25), c1(0.2), c2(0.0, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(m::lambert(0.5), 0.5);
  EXPECT_DOUBLE_EQ(m::lambert(-0.5), 0.0);
  EXPECT_DOUBLE_EQ(m::wrapAround(0.5, 0.5), 1.0 / 1.5);
  EXPECT_DOUBLE_EQ(m::wrapAround(-0.25, 0.5), 0.25 / 1.5);
  EXPECT_DOUBLE_EQ(m::wrapAround(-0.75, 0.5), 0.0);
  expectNear(m::hemispherical(0.5, c0, c2), dvec3(0.75, 0.375, 0.4375), 1e-15);
  expectNear(m::hemispherical(-1.0, c0, c2), c2, 1e-15);
  expectNear(m::biDirectional(0.5, c0, c2), dvec3(0.5, 0.25, 0.125), 1e-15);
  expectNear(m::biDirectional(-0.5, c0, c2), dvec3(0.0, 0.0, 0.5), 1e-15);
  expectNear(m::trilight(0.5, c0, c1, c2), dvec3(0.6, 0.35, 0.225), 1e-15);
  expectNear(m::trilight(-0.5, c0, c1, c2), dvec3(0.1, 0.1, 0.6), 1e-15);
}

// Seed 002: trilight = Lambert when c1 = c2 = 0, = bi-directional when
// c1 = 0, = hemispherical exactly when c1 = (c0 + c2) / 2.
TEST(Models, TrilightIdentitiesOverManyNdotL) {
  const dvec3 c0(0.9, 0.6, 0.3), c2(0.1, 0.3, 0.7);
  double max_lambert = 0, max_bidir = 0, max_hemi = 0, max_hemi_off = 0;
  for (int i = -10000; i <= 10000; ++i) {
    double x = i / 10000.0;
    auto d = [](dvec3 a, dvec3 b) { return glm::length(a - b); };
    max_lambert = std::max(max_lambert, d(m::trilight(x, c0, dvec3(0), dvec3(0)), c0 * m::lambert(x)));
    max_bidir = std::max(max_bidir, d(m::trilight(x, c0, dvec3(0), c2), m::biDirectional(x, c0, c2)));
    max_hemi = std::max(max_hemi, d(m::trilight(x, c0, (c0 + c2) * 0.5, c2), m::hemispherical(x, c0, c2)));
    max_hemi_off = std::max(max_hemi_off, d(m::trilight(x, c0, (c0 + c2) * 0.5 + 0.01, c2),
                                            m::hemispherical(x, c0, c2)));
  }
  EXPECT_EQ(max_lambert, 0.0);
  EXPECT_EQ(max_bidir, 0.0);
  EXPECT_LT(max_hemi, 1e-15);
  // "exactly when": any other c1 differs (by 0.01 (1 - |x|) per channel).
  EXPECT_NEAR(max_hemi_off, 0.01 * std::sqrt(3.0), 1e-12);
}

// Seed 002: with c2 = 0 and c1 = f c0 / 2 the trilight approximates
// wrap-around; exact at f = 0 and f = 1, worst at f = 0.5, where at
// x = -0.5 the trilight gives f/2 (x + 1) = 0.125 and wrap-around 0.
TEST(Models, TrilightApproximatesWrapAroundWorstAtHalf) {
  const dvec3 c0(1.0);
  double worst_f = -1, worst_err = -1;
  for (int k = 0; k <= 100; ++k) {
    double f = k / 100.0, err = 0;
    for (int i = -10000; i <= 10000; ++i) {
      double x = i / 10000.0;
      err = std::max(err, std::abs(m::trilight(x, c0, c0 * (f / 2), dvec3(0)).x -
                                   m::wrapAround(x, f)));
    }
    if (k == 0 || k == 100) EXPECT_LT(err, 1e-15) << "f = " << f;
    else EXPECT_GT(err, 1e-4) << "f = " << f;
    if (err > worst_err) worst_err = err, worst_f = f;
  }
  EXPECT_DOUBLE_EQ(worst_f, 0.5);
  EXPECT_NEAR(worst_err, 0.125, 1e-12);
}

TEST(Models, YiqMatricesAreInversesAndFirstColumnIsOnes) {
  for (int r = 0; r < 3; ++r) EXPECT_EQ(m::kYiqToRgb[r][0], 1.0);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += m::kYiqToRgb[r][k] * m::kRgbToYiq[k][c];
      EXPECT_NEAR(s, r == c ? 1.0 : 0.0, 2e-8) << r << "," << c;
    }
  }
}

TEST(Models, YiqRoundTrip) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 10000; ++i) {
    dvec3 c(u(rng), u(rng), u(rng));
    expectNear(m::yiqToRgb(m::rgbToYiq(c)), c, 1e-7);
  }
  // Hand value: luma of (0.5, 0.25, 0.1).
  EXPECT_NEAR(m::luma(dvec3(0.5, 0.25, 0.1)), 0.3075514955, 1e-12);
}

// The listing's round trip equals saturate(C + (Y' - Y)(1,1,1)).
TEST(Models, YiqListingEqualsReducedForm) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0;
  for (int i = 0; i < 100000; ++i) {
    dvec3 c(u(rng), u(rng), u(rng));
    double dl = u(rng) * 1.2, s = u(rng), off = 0.1;
    dvec3 a = m::saturate(m::yiqLumaListing(c, dl, s, off));
    dvec3 b = m::saturate(m::yiqLuma(c, dl, s, off));
    worst = std::max(worst, glm::length(a - b));
  }
  EXPECT_LT(worst, 1e-7);
}

TEST(Models, YiqHandValues) {
  const dvec3 c(0.5, 0.25, 0.1);
  // Head-on light, A = 0.1: Dl = 1, S = 1, Y' = Y + 0.9: every channel + 0.9.
  expectNear(m::yiqLuma(c, 1.0, 1.0, 0.1), dvec3(1.4, 1.15, 1.0), 1e-12);
  // Dl = 0.8071067812, S = 0.5: dY = Y (Dl - 1) + 0.4 = 0.3406754021.
  expectNear(m::yiqLuma(c, std::sqrt(0.5) + 0.1, 0.5, 0.1),
             dvec3(0.8406754021, 0.5906754021, 0.4406754021), 1e-9);
}
