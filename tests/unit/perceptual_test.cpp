// Perceptual metrics against published reference values.
#include <gtest/gtest.h>

#include "image/perceptual.h"

using namespace xval;
using glm::dvec3;

// Sharma, Wu, Dalal (2005), Table 1: the 34 CIEDE2000 test pairs (pair 8
// is pair 7 reversed: the symmetry check covers it; the hue wrap-around,
// the achromatic case, large differences, dark colours), and three pairs
// near L* 84.
TEST(Perceptual, Ciede2000MatchesSharmaTestData) {
  struct Pair { dvec3 a, b; double de; };
  const Pair pairs[] = {
      {{50.0000, 2.6772, -79.7751}, {50.0000, 0.0000, -82.7485}, 2.0425},
      {{50.0000, 3.1571, -77.2803}, {50.0000, 0.0000, -82.7485}, 2.8615},
      {{50.0000, 2.8361, -74.0200}, {50.0000, 0.0000, -82.7485}, 3.4412},
      {{50.0000, -1.3802, -84.2814}, {50.0000, 0.0000, -82.7485}, 1.0000},
      {{50.0000, -1.1848, -84.8006}, {50.0000, 0.0000, -82.7485}, 1.0000},
      {{50.0000, -0.9009, -85.5211}, {50.0000, 0.0000, -82.7485}, 1.0000},
      {{50.0, 2.5, 0.0}, {73.0, 25.0, -18.0}, 27.1492},
      {{50.0, 2.5, 0.0}, {61.0, -5.0, 29.0}, 22.8977},
      {{50.0, 2.5, 0.0}, {56.0, -27.0, -3.0}, 31.9030},
      {{50.0, 2.5, 0.0}, {58.0, 24.0, 15.0}, 19.4535},
      {{84.25, 5.74, 96.0}, {84.46, 8.88, 96.49}, 1.6743},
      {{84.25, 5.74, 96.0}, {84.52, 5.75, 93.09}, 0.5887},
      {{84.25, 5.74, 96.0}, {84.37, 5.86, 99.42}, 0.6395},
      {{50.0, 0.0, 0.0}, {50.0, -1.0, 2.0}, 2.3669},
      {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0009}, 7.1792},
      {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0010}, 7.1792},
      {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0011}, 7.2195},
      {{50.0, 2.49, -0.001}, {50.0, -2.49, 0.0012}, 7.2195},
      {{50.0, -0.001, 2.49}, {50.0, 0.0009, -2.49}, 4.8045},
      {{50.0, -0.001, 2.49}, {50.0, 0.0010, -2.49}, 4.8045},
      {{50.0, -0.001, 2.49}, {50.0, 0.0011, -2.49}, 4.7461},
      {{50.0, 2.5, 0.0}, {50.0, 0.0, -2.5}, 4.3065},
      {{50.0, 2.5, 0.0}, {50.0, 3.1736, 0.5854}, 1.0000},
      {{50.0, 2.5, 0.0}, {50.0, 3.2972, 0.0}, 1.0000},
      {{50.0, 2.5, 0.0}, {50.0, 1.8634, 0.5757}, 1.0000},
      {{50.0, 2.5, 0.0}, {50.0, 3.2592, 0.3350}, 1.0000},
      {{60.2574, -34.0099, 36.2677}, {60.4626, -34.1751, 39.4387}, 1.2644},
      {{63.0109, -31.0961, -5.8663}, {62.8187, -29.7946, -4.0864}, 1.2630},
      {{61.2901, 3.7196, -5.3901}, {61.4292, 2.2480, -4.9620}, 1.8731},
      {{35.0831, -44.1164, 3.7933}, {35.0232, -40.0716, 1.5901}, 1.8645},
      {{22.7233, 20.0904, -46.6940}, {23.0331, 14.9730, -42.5619}, 2.0373},
      {{36.4612, 47.8580, 18.3852}, {36.2715, 50.5065, 21.2231}, 1.4146},
      {{90.8027, -2.0831, 1.4410}, {91.1528, -1.6435, 0.0447}, 1.4441},
      {{90.9257, -0.5406, -0.9208}, {88.6381, -0.8985, -0.7239}, 1.5381},
      {{6.7747, -0.2908, -2.4247}, {5.8714, -0.0985, -2.2286}, 0.6377},
      {{2.0776, 0.0795, -1.1350}, {0.9033, -0.0636, -0.5514}, 0.9082},
  };
  for (const auto& p : pairs) {
    EXPECT_NEAR(ciede2000(p.a, p.b), p.de, 5e-5) << p.a.x << " " << p.a.y << " " << p.a.z;
    EXPECT_NEAR(ciede2000(p.b, p.a), p.de, 5e-5);  // symmetric
  }
}

TEST(Perceptual, SrgbToLabKnownColours) {
  dvec3 white = srgbToLab(dvec3(1.0));
  EXPECT_NEAR(white.x, 100.0, 1e-3);
  EXPECT_NEAR(white.y, 0.0, 1e-3);
  EXPECT_NEAR(white.z, 0.0, 1e-3);
  dvec3 black = srgbToLab(dvec3(0.0));
  EXPECT_NEAR(black.x, 0.0, 1e-9);
  // sRGB red is L* 53.24, a* 80.09, b* 67.20 (D65).
  dvec3 red = srgbToLab(dvec3(1, 0, 0));
  EXPECT_NEAR(red.x, 53.24, 0.01);
  EXPECT_NEAR(red.y, 80.09, 0.02);
  EXPECT_NEAR(red.z, 67.20, 0.02);
}

// Kotsarenko & Ramos (2010): weights 0.5053, 0.299, 0.1957 on dY, dI, dQ.
TEST(Perceptual, YiqDeltaHandValues) {
  EXPECT_EQ(yiqDelta(dvec3(0.3), dvec3(0.3)), 0.0);
  // Black vs white: dY = 1.00000001 (the listing's row sum), dI = dQ ~ 0.
  EXPECT_NEAR(yiqDelta(dvec3(0.0), dvec3(1.0)), std::sqrt(0.5053), 1e-7);
  // A pure red step of 0.1: dY = 0.029889531, dI = 0.059597799, dQ = 0.021147017.
  double e = std::sqrt(0.5053 * 0.029889531 * 0.029889531 + 0.299 * 0.059597799 * 0.059597799 +
                       0.1957 * 0.021147017 * 0.021147017);
  EXPECT_NEAR(yiqDelta(dvec3(0.5, 0.2, 0.2), dvec3(0.6, 0.2, 0.2)), e, 1e-12);
}

TEST(Perceptual, SsimOfIdenticalImagesIsOneAndOfConstantsIsTheLuminanceTerm) {
  Image a(32, 32, false), b(32, 32, false);
  for (size_t i = 0; i < a.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) a.rgba[i + c] = 0.5f, b.rgba[i + c] = 0.25f;
    a.rgba[i + 3] = b.rgba[i + 3] = 1.0f;
  }
  EXPECT_NEAR(perceptualMetrics(a, a).ssim, 1.0, 1e-12);
  // Constant images: no variance, SSIM = (2 ma mb + C1) / (ma^2 + mb^2 + C1).
  double ma = 0.5 * 1.00000001, mb = 0.25 * 1.00000001, C1 = 1e-4;
  EXPECT_NEAR(perceptualMetrics(a, b).ssim, (2 * ma * mb + C1) / (ma * ma + mb * mb + C1), 1e-6);
}
