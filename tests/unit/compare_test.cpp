// compareImages and Tolerance::passes on small hand-built images
// (image/compare.h): hit masks and silhouettes, the 99.9th percentile, the
// worst pixel, the histogram and the classes of over-tolerance pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "image/compare.h"

namespace xval {
namespace {

// w x h, every pixel covered (alpha 1) with colour 0, with diagnostics
// that explain nothing: depth 1, front-facing, incidence 1.
Image covered(int w, int h, bool diagnostics = false) {
  Image img(w, h, diagnostics);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) img.pixel(x, y)[3] = 1.0f;
  if (diagnostics) {
    std::fill(img.depth.begin(), img.depth.end(), 1.0f);
    std::fill(img.incidence.begin(), img.incidence.end(), 1.0f);
  }
  return img;
}

void uncover(Image& img, int x0, int y0, int x1, int y1) {
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) img.pixel(x, y)[0] = img.pixel(x, y)[1] = img.pixel(x, y)[2] = img.pixel(x, y)[3] = 0.0f;
}

// No cap on unexplained pixels unless given: these tests are about the
// fraction rule (the cap has its own tests below).
Tolerance tolerance(double max_abs, double fraction,
                    double max_unexplained = std::numeric_limits<double>::infinity()) {
  Tolerance t;
  t.max_abs = max_abs, t.fraction = fraction, t.max_unexplained = max_unexplained;
  return t;
}

TEST(CompareImages, EqualImagesHaveNoErrorAndPass) {
  const Image a = covered(4, 3);
  const CompareMetrics m = compareImages(a, a, tolerance(0.0, 1.0));
  EXPECT_EQ(m.covered_both, 12);
  EXPECT_EQ(m.mask_disagree, 0);
  EXPECT_EQ(m.max_abs, 0.0);
  EXPECT_EQ(m.p999_abs, 0.0);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr_db));
  EXPECT_EQ(m.fraction_within, 1.0);
  EXPECT_EQ(m.worst_x, 0);  // the first pixel when nothing differs
  EXPECT_EQ(m.worst_y, 0);
  EXPECT_TRUE(tolerance(0.0, 1.0).passes(m));
}

TEST(CompareImages, RefusesImagesOfDifferentSizes) {
  EXPECT_THROW(compareImages(covered(4, 3), covered(3, 4), tolerance(0, 1)), std::runtime_error);
}

// A pixel one image misses is a mask disagreement; on a silhouette when
// its 3x3 neighbourhood holds hits and misses in either image.
TEST(CompareImages, MaskDisagreementOnASilhouetteIsTold) {
  Image a = covered(8, 8), b = covered(8, 8);
  uncover(a, 0, 0, 7, 1), uncover(b, 0, 0, 7, 1);  // both miss rows 0-1
  uncover(b, 0, 2, 7, 2);                          // b misses row 2 too: the edge moved by a row
  const CompareMetrics m = compareImages(a, b, tolerance(0, 1));
  EXPECT_EQ(m.mask_disagree, 8);
  EXPECT_EQ(m.mask_disagree_silhouette, 8);
  EXPECT_EQ(m.covered_both, 8 * 5);
  EXPECT_TRUE(tolerance(0, 1).passes(m));  // silhouette disagreements are allowed
}

TEST(CompareImages, MaskDisagreementOffSilhouettesFails) {
  Image a = covered(9, 9), b = covered(9, 9);
  uncover(b, 3, 3, 5, 5);  // a 3x3 hole inside b
  const CompareMetrics m = compareImages(a, b, tolerance(1, 0));
  EXPECT_EQ(m.mask_disagree, 9);
  // The hole's centre: all hits around it in a, all misses in b.
  EXPECT_EQ(m.mask_disagree_silhouette, 8);
  EXPECT_EQ(m.covered_both, 81 - 9);
  EXPECT_FALSE(tolerance(1, 0).passes(m));  // however loose the colour tolerance
}

// 1000 covered pixels with errors 0..999 (x 2^-16, exact in float), placed
// so that the largest is at pixel 857 = (7, 17) of a 50 x 20 image.
struct KnownErrors {
  Image a = covered(50, 20), b = covered(50, 20);
  KnownErrors() {
    for (int p = 0; p < 1000; ++p) {
      const int i = (p * 7) % 1000;  // a permutation of 0..999
      b.pixel(p % 50, p / 50)[1] = float(i) / 65536.0f;
    }
  }
};

TEST(CompareImages, PercentileIsTheNearestRankOfThePixelErrors) {
  KnownErrors k;
  const CompareMetrics m = compareImages(k.a, k.b, tolerance(2.0 / 65536.0, 0.5));
  EXPECT_EQ(m.covered_both, 1000);
  // Nearest rank: the ceil(0.999 * 1000) = 999th smallest, i.e. 998.
  EXPECT_EQ(m.p999_abs, 998.0 / 65536.0);
  EXPECT_EQ(m.max_abs, 999.0 / 65536.0);
  EXPECT_EQ(m.worst_x, 7);
  EXPECT_EQ(m.worst_y, 17);
  // RMSE over 3 channels: sqrt(sum i^2 / 3000), sum i^2 = 999 * 1000 * 1999 / 6.
  EXPECT_NEAR(m.rmse, std::sqrt(999.0 * 1000.0 * 1999.0 / 6.0 / 3000.0) / 65536.0, 1e-12);
  EXPECT_NEAR(m.psnr_db, 20.0 * std::log10(1.0 / m.rmse), 1e-9);
  // Within 2/65536: errors 0, 1 and 2.
  EXPECT_EQ(m.fraction_within, 0.003);
  EXPECT_EQ(m.over_tolerance, 997);
  EXPECT_EQ(m.over_unexplained, 997);  // no diagnostics: nothing is explained
}

TEST(CompareImages, HistogramCountsPixelsByErrorIn16BitSteps) {
  KnownErrors k;
  const CompareMetrics m = compareImages(k.a, k.b, tolerance(0, 1));
  // i / 65536 is i * 0.99998 in 1/65535: <= 0.5: {0}; <= 1: {1}; <= 2: {2};
  // <= 4: {3, 4}; <= 16: 5..16; <= 256: 17..256; above: 257..999.
  const long long expected[7] = {1, 1, 1, 2, 12, 240, 743};
  for (int bin = 0; bin < 7; ++bin) EXPECT_EQ(m.histogram[bin], expected[bin]) << "bin " << bin;
}

TEST(CompareImages, PixelsOutsideEitherMaskAreLeftOutOfTheColourMetrics) {
  Image a = covered(4, 4), b = covered(4, 4);
  uncover(a, 0, 0, 3, 0), uncover(b, 0, 0, 3, 0);
  b.pixel(1, 0)[0] = 1.0f;  // a colour where neither hits (not covered by b: alpha 0)
  const CompareMetrics m = compareImages(a, b, tolerance(0, 1));
  EXPECT_EQ(m.covered_both, 12);
  EXPECT_EQ(m.max_abs, 0.0);
}

TEST(CompareImages, NonFiniteColourIsAnInfiniteError) {
  Image a = covered(3, 3), b = covered(3, 3);
  b.pixel(2, 1)[2] = std::numeric_limits<float>::quiet_NaN();
  const CompareMetrics m = compareImages(a, b, tolerance(1.0, 0.0));
  EXPECT_TRUE(std::isinf(m.max_abs));
  EXPECT_EQ(m.worst_x, 2);
  EXPECT_EQ(m.worst_y, 1);
  EXPECT_EQ(m.over_tolerance, 1);
}

// Over-tolerance pixels by cause, from the first image's diagnostics, in
// the order backfacing normal, occlusion edge, grazing, unexplained.
TEST(CompareImages, OverTolerancePixelsAreClassifiedByTheirCause) {
  Image a = covered(7, 7, true), b = covered(7, 7);
  auto at = [&](std::vector<float>& channel, int x, int y) -> float& { return channel[size_t(y) * 7 + x]; };
  at(a.depth, 0, 0) = 2.0f;         // a depth jump: (1, 1) is on an occlusion edge
  at(a.backfacing, 3, 3) = 1.0f;    // backfacing ...
  at(a.incidence, 3, 3) = 0.05f;    // ... and grazing: backfacing counts first
  at(a.incidence, 5, 1) = 0.05f;    // grazing
  for (auto [x, y] : {std::pair{1, 1}, {3, 3}, {5, 1}, {3, 5}}) b.pixel(x, y)[0] = 0.25f;
  b.pixel(5, 5)[0] = 0.125f;        // exactly at the tolerance: within
  const Tolerance t = tolerance(0.125, 0.5);
  const CompareMetrics m = compareImages(a, b, t);
  EXPECT_EQ(m.over_tolerance, 4);
  EXPECT_EQ(m.over_occlusion_edge, 1);
  EXPECT_EQ(m.over_backfacing, 1);
  EXPECT_EQ(m.over_grazing, 1);
  EXPECT_EQ(m.over_unexplained, 1);
  EXPECT_EQ(m.backfacing_pixels, 1);
  EXPECT_EQ(m.covered_both, 49);
  EXPECT_EQ(m.fraction_within, 45.0 / 49.0);
  // Per class, the largest error; the worst of each kind and where.
  EXPECT_EQ(m.over_max[size_t(PixelClass::OcclusionEdge)], 0.25);
  EXPECT_EQ(m.over_max[size_t(PixelClass::TexelBoundary)], 0.0);
  EXPECT_EQ(m.max_unexplained, 0.25);
  EXPECT_EQ(m.worst_unexplained_x, 3);
  EXPECT_EQ(m.worst_unexplained_y, 5);
  EXPECT_EQ(m.max_explained, 0.25);
  EXPECT_EQ(m.worst_explained_x, 1);  // the first of the explained 0.25s in row order
  EXPECT_EQ(m.worst_explained_y, 1);
  // Pixels on the image border have neighbours outside it: occlusion edges.
  Image edge = covered(7, 7);
  edge.pixel(0, 3)[0] = 0.25f;
  EXPECT_EQ(compareImages(a, edge, t).over_occlusion_edge, 1);
}

TEST(CompareImages, ExcludeBackfacingLeavesThoseOutOfTheColourMetrics) {
  Image a = covered(5, 5, true), b = covered(5, 5);
  a.backfacing[2 * 5 + 2] = 0.5f;
  b.pixel(2, 2)[1] = 1.0f;
  Tolerance t = tolerance(0.0, 1.0);
  t.exclude_backfacing = true;
  const CompareMetrics m = compareImages(a, b, t);
  EXPECT_EQ(m.backfacing_pixels, 1);  // still counted
  EXPECT_EQ(m.covered_both, 24);
  EXPECT_EQ(m.max_abs, 0.0);
  EXPECT_TRUE(t.passes(m));
  t.exclude_backfacing = false;
  EXPECT_FALSE(t.passes(compareImages(a, b, t)));
}

// Tolerance::passes: each condition on its own.
TEST(TolerancePasses, FractionWithinMustReachTheDeclaredFraction) {
  CompareMetrics m;
  m.covered_both = 1000;
  m.fraction_within = 0.999;
  EXPECT_TRUE(tolerance(0, 0.999).passes(m));  // equal is enough
  m.fraction_within = 0.998999;
  EXPECT_FALSE(tolerance(0, 0.999).passes(m));
}

TEST(TolerancePasses, MaskDisagreementsOffSilhouettesFail) {
  CompareMetrics m;
  m.covered_both = 10;
  m.mask_disagree = 3, m.mask_disagree_silhouette = 3;
  EXPECT_TRUE(tolerance(0, 1).passes(m));
  m.mask_disagree_silhouette = 2;
  EXPECT_FALSE(tolerance(0, 1).passes(m));
}

TEST(TolerancePasses, NothingCoveredByBothFails) {
  CompareMetrics m;  // fraction_within 1, no mask disagreement
  m.covered_both = 0;
  EXPECT_FALSE(tolerance(1, 0).passes(m));
  m.covered_both = 1;
  EXPECT_TRUE(tolerance(1, 0).passes(m));
}

TEST(TolerancePasses, TheEmptyToleranceAcceptsOnlyEqualImages) {
  Image a = covered(3, 3), b = covered(3, 3);
  EXPECT_TRUE(Tolerance{}.passes(compareImages(a, b, Tolerance{})));
  b.pixel(1, 1)[0] = 1.0f / 65536.0f;
  EXPECT_FALSE(Tolerance{}.passes(compareImages(a, b, Tolerance{})));
}

// A nearest-filtered lookup within kTexelEdgeRoundings float roundings of
// the uv from a texel edge explains its pixel; one just beyond does not.
TEST(CompareImages, TexelBoundaryPixelsAreExplainedByTheReferenceChannel) {
  Image a = covered(7, 7, true), b = covered(7, 7);
  ASSERT_EQ(a.texel_edge.size(), 49u);
  a.texel_edge[3 * 7 + 3] = kTexelEdgeRoundings;         // on the limit: near
  a.texel_edge[3 * 7 + 4] = kTexelEdgeRoundings * 1.01f;  // beyond it
  b.pixel(3, 3)[1] = 0.5f;
  b.pixel(4, 3)[1] = 0.25f;
  const CompareMetrics m = compareImages(a, b, tolerance(0.0, 0.5));
  EXPECT_EQ(m.over_texel_boundary, 1);
  EXPECT_EQ(m.over_max[size_t(PixelClass::TexelBoundary)], 0.5);
  EXPECT_EQ(m.over_unexplained, 1);
  EXPECT_EQ(m.max_unexplained, 0.25);
  EXPECT_EQ(m.worst_unexplained_x, 4);
  // The classification reads either image's channel (a copy of the
  // reference's given to another renderer's image counts the same).
  EXPECT_EQ(classifyPixel(b, a, 3, 3), PixelClass::TexelBoundary);
  EXPECT_EQ(classifyPixel(b, b, 3, 3), PixelClass::Unexplained);
}

// The hard cap: one wrong pixel in 10,000 is within a 99.9% fraction, and
// fails the case all the same when nothing explains it.
TEST(CompareImages, ASingleUnexplainedPixelOverTheCapFailsWhateverTheFraction) {
  Image a = covered(100, 100, true), b = covered(100, 100);
  const double cap = 8.0 / 65535.0;
  b.pixel(50, 50)[2] = float(9.0 / 65535.0);
  const Tolerance t = tolerance(2.0 / 65535.0, 0.999, cap);
  CompareMetrics m = compareImages(a, b, t);
  EXPECT_GE(m.fraction_within, 0.999);
  EXPECT_NEAR(m.max_unexplained * 65535.0, 9.0, 1e-3);
  EXPECT_EQ(m.worst_unexplained_x, 50);
  EXPECT_EQ(m.worst_unexplained_y, 50);
  EXPECT_FALSE(t.passes(m));
  // At the cap it passes; the same pixel explained (a grazing ray) passes
  // however large.
  b.pixel(50, 50)[2] = float(cap);
  EXPECT_TRUE(t.passes(compareImages(a, b, t)));
  b.pixel(50, 50)[2] = 1.0f;
  a.incidence[50 * 100 + 50] = 0.05f;
  m = compareImages(a, b, t);
  EXPECT_EQ(m.over_grazing, 1);
  EXPECT_EQ(m.max_unexplained, 0.0);
  EXPECT_EQ(m.worst_unexplained_x, -1);
  EXPECT_TRUE(t.passes(m));
  // A pixel within the tolerance but unexplained still counts for the
  // largest unexplained error (the cap bounds every unexplained pixel).
  b.pixel(10, 10)[0] = float(1.0 / 65535.0);
  EXPECT_NEAR(compareImages(a, b, t).max_unexplained * 65535.0, 1.0, 1e-3);
  // Tolerance{} accepts only equal images.
  EXPECT_FALSE(Tolerance{}.passes(compareImages(a, b, Tolerance{})));
}

TEST(CompareImages, MetricsJsonGivesTheCountAndMaxOfEveryClass) {
  Image a = covered(7, 7, true), b = covered(7, 7);
  a.texel_edge[3 * 7 + 3] = 1.0f;
  b.pixel(3, 3)[0] = 0.5f;
  b.pixel(3, 4)[0] = float(3.0 / 65535.0);
  const nlohmann::json j = metricsJson(compareImages(a, b, tolerance(1.0 / 65535.0, 0.5)));
  for (const PixelClassInfo& c : kPixelClasses) {
    EXPECT_TRUE(j["over_tolerance"].contains(c.key)) << c.key;
    EXPECT_TRUE(j["over_tolerance_max_16bit"].contains(c.key)) << c.key;
  }
  EXPECT_EQ(j["over_tolerance"]["texel_boundary"], 1);
  EXPECT_NEAR(j["over_tolerance_max_16bit"]["texel_boundary"].get<double>(), 0.5 * 65535.0, 1e-6);
  EXPECT_NEAR(j["max_unexplained_16bit"].get<double>(), 3.0, 1e-3);
  EXPECT_EQ(j["worst_unexplained_pixel"], nlohmann::json::array({3, 4}));
  EXPECT_EQ(j["worst_explained_pixel"], nlohmann::json::array({3, 3}));
}

}  // namespace
}  // namespace xval
