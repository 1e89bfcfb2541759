// compareImages and Tolerance::passes on small hand-built images
// (image/compare.h): hit masks and their edge bound, the 99.9th percentile,
// the worst pixel, the histogram and the classes of over-tolerance pixels
// with their bounds (image/pixel_classes.h).
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
    for (auto* c : {&img.edge_fraction, &img.backfacing_flip, &img.precision_position, &img.precision_uv,
                    &img.precision_normal})
      c->assign(size_t(w) * h, 0.0f);
  }
  return img;
}

float& channelAt(std::vector<float>& channel, const Image& img, int x, int y) {
  return channel[size_t(y) * img.width + x];
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

// A pixel one image misses is a mask disagreement, explained only when the
// reference's edge samples account for its whole coverage difference.
TEST(CompareImages, AMaskDisagreementIsExplainedOnlyByEdgeSamples) {
  Image a = covered(8, 8, true), b = covered(8, 8);
  uncover(a, 0, 0, 7, 1), uncover(b, 0, 0, 7, 1);  // both miss rows 0-1
  uncover(b, 0, 2, 7, 2);                          // b misses row 2 too: the edge moved by a row
  for (int x = 0; x < 8; ++x) channelAt(a.edge_fraction, a, x, 2) = 1.0f;  // every sample within 2^-8 px of it
  CompareMetrics m = compareImages(a, b, tolerance(0, 1));
  EXPECT_EQ(m.mask_disagree, 8);
  EXPECT_EQ(m.mask_disagree_explained, 8);
  EXPECT_EQ(m.covered_both, 8 * 5);
  EXPECT_TRUE(tolerance(0, 1).passes(m));
  // A quarter of the samples near the edge cannot explain a whole pixel.
  channelAt(a.edge_fraction, a, 3, 2) = 0.25f;
  m = compareImages(a, b, tolerance(0, 1));
  EXPECT_EQ(m.mask_disagree_explained, 7);
  EXPECT_FALSE(tolerance(0, 1).passes(m));
  // ... but it explains a pixel whose coverage differs by a quarter.
  b.pixel(3, 2)[3] = 0.75f, b.pixel(3, 2)[0] = 0.0f;
  a.pixel(3, 2)[3] = 0.5f;
  m = compareImages(a, b, tolerance(0, 1));
  EXPECT_EQ(m.mask_disagree, 7);
  EXPECT_EQ(m.overCount(PixelClass::Edge), 0);  // colours equal: within
  EXPECT_EQ(m.max_unexplained, 0.0);
  // Without the reference's diagnostics nothing is explained.
  const Image plain = covered(8, 8);
  Image hole = covered(8, 8);
  uncover(hole, 0, 2, 7, 2);
  EXPECT_EQ(compareImages(plain, hole, tolerance(1, 0)).mask_disagree_explained, 0);
}

// The holes the old silhouette rule excused (a missing pixel next to a hit
// was "on a silhouette"): every odd row missing, a hole inside a surface.
TEST(CompareImages, MissingRowsAndHolesAreNeverExplainedAwayFromEdges) {
  Image a = covered(9, 9, true), b = covered(9, 9);
  uncover(b, 3, 3, 5, 5);  // a 3x3 hole inside b
  CompareMetrics m = compareImages(a, b, tolerance(1, 0));
  EXPECT_EQ(m.mask_disagree, 9);
  EXPECT_EQ(m.mask_disagree_explained, 0);
  EXPECT_EQ(m.covered_both, 81 - 9);
  EXPECT_FALSE(tolerance(1, 0).passes(m));  // however loose the colour tolerance
  Image rows = covered(9, 9);
  for (int y = 1; y < 9; y += 2) uncover(rows, 0, y, 8, y);
  m = compareImages(a, rows, tolerance(1, 0));
  EXPECT_EQ(m.mask_disagree, 36);
  EXPECT_EQ(m.mask_disagree_explained, 0);
  EXPECT_FALSE(tolerance(1, 0).passes(m));
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
  EXPECT_EQ(m.over_unexplained(), 997);  // no diagnostics: nothing is explained
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

// Over-tolerance pixels by cause, each explained up to its bound and no
// further: an edge by its share of edge samples, a backfacing normal by
// what turning it changes, precision by the pair's bound.
TEST(CompareImages, OverTolerancePixelsAreExplainedUpToTheirCausesBound) {
  Image a = covered(7, 7, true), b = covered(7, 7);
  channelAt(a.edge_fraction, a, 1, 1) = 0.25f;     // edge: up to 0.25
  channelAt(a.edge_fraction, a, 1, 3) = 0.25f;
  channelAt(a.backfacing, a, 3, 3) = 1.0f;         // backfacing: up to 0.5
  channelAt(a.backfacing_flip, a, 3, 3) = 0.5f;
  channelAt(a.backfacing, a, 3, 1) = 1.0f;
  channelAt(a.backfacing_flip, a, 3, 1) = 0.5f;
  channelAt(a.precision_position, a, 5, 1) = 0.01f;  // precision: 2 x 0.01 with one step each
  channelAt(a.precision_position, a, 5, 3) = 0.01f;
  b.pixel(1, 1)[0] = 0.25f;   // edge, at its bound
  b.pixel(1, 3)[0] = 0.375f;  // beyond it
  b.pixel(3, 3)[0] = 0.5f;    // backfacing, at its bound
  b.pixel(3, 1)[0] = 0.625f;  // beyond it
  b.pixel(5, 1)[0] = 0.015f;  // precision
  b.pixel(5, 3)[0] = 0.03f;   // beyond it
  b.pixel(5, 5)[0] = 0.125f;  // nothing explains it
  b.pixel(0, 6)[0] = 0.0005f;  // within the tolerance
  PrecisionModel one;
  one.position_steps = 1.0;
  const Tolerance t = tolerance(0.001, 0.5);
  const CompareMetrics m = compareImages(a, b, t, {one, one});
  EXPECT_EQ(m.over_tolerance, 7);
  EXPECT_EQ(m.overCount(PixelClass::Edge), 1);
  EXPECT_EQ(m.overCount(PixelClass::BackfacingNormal), 1);
  EXPECT_EQ(m.overCount(PixelClass::Precision), 1);
  EXPECT_EQ(m.over_unexplained(), 4);
  EXPECT_EQ(m.backfacing_pixels, 2);
  EXPECT_EQ(m.covered_both, 49);
  // Explained pixels count as within: only the 4 unexplained are outside.
  EXPECT_EQ(m.fraction_within, 45.0 / 49.0);
  EXPECT_NEAR(m.max_precision_bound, 0.02, 1e-7);
  // Per class, the largest error; the worst of each kind and where.
  EXPECT_EQ(m.over_max[size_t(PixelClass::Edge)], 0.25);
  EXPECT_EQ(m.over_max[size_t(PixelClass::BackfacingNormal)], 0.5);
  EXPECT_FLOAT_EQ(m.over_max[size_t(PixelClass::Unexplained)], 0.625);
  EXPECT_EQ(m.worst_unexplained_x, 3);
  EXPECT_EQ(m.worst_unexplained_y, 1);
  EXPECT_EQ(m.max_explained, 0.5);
  EXPECT_EQ(m.worst_explained_x, 3);
  EXPECT_EQ(m.worst_explained_y, 3);
  EXPECT_EQ(m.worst_explained_class, PixelClass::BackfacingNormal);
  // Without precision models the precision pixel is unexplained.
  EXPECT_EQ(compareImages(a, b, t).over_unexplained(), 5);
}

// The class rule on its own (image/pixel_classes.h).
TEST(PixelClasses, EachCauseExplainsUpToItsBound) {
  const double tol = 2.0 / 65535.0;
  PixelBounds b;
  b.precision = 0.01;
  EXPECT_EQ(classifyPixel(0.01 + tol, 0.0, tol, b), PixelClass::Precision);
  EXPECT_EQ(classifyPixel(0.0101 + tol, 0.0, tol, b), PixelClass::Unexplained);
  b.edge = 0.25;
  EXPECT_EQ(classifyPixel(0.26 + tol, 0.0, tol, b), PixelClass::Edge);
  EXPECT_EQ(classifyPixel(0.27 + tol, 0.0, tol, b), PixelClass::Unexplained);
  EXPECT_EQ(classifyPixel(0.1, 0.5, tol, b), PixelClass::Unexplained);  // coverage beyond the edge samples
  b.backfacing = 0.5;
  EXPECT_EQ(classifyPixel(0.7, 0.0, tol, b), PixelClass::BackfacingNormal);
  EXPECT_EQ(classifyPixel(0.8, 0.0, tol, b), PixelClass::Unexplained);
  EXPECT_EQ(classifyPixel(std::numeric_limits<double>::quiet_NaN(), 0.0, tol, b), PixelClass::Unexplained);
  EXPECT_TRUE(maskDisagreementExplained(0.25, PixelBounds{0.25, 0, 0}));
  EXPECT_FALSE(maskDisagreementExplained(0.5, PixelBounds{0.25, 0, 1}));
}

// B_r(p) = steps x probe + relative |v| + quantum, a pair's the sum of both;
// either image's channels count (a copy of the reference's given to
// another renderer's image).
TEST(PrecisionBound, IsTheDeclaredStepsTimesTheProbesPlusRelativeAndQuantum) {
  Image d = covered(2, 1, true);
  channelAt(d.precision_position, d, 1, 0) = 0.001f;
  channelAt(d.precision_uv, d, 1, 0) = 0.002f;
  channelAt(d.precision_normal, d, 1, 0) = 0.004f;
  PrecisionModel m{2.0, 3.0, 0.5, 0.01, 4.0, "test"};
  EXPECT_NEAR(precisionBound(d, 1, 0, 0.5, m), 2 * 0.001 + 3 * 0.002 + 0.5 * 0.004 + 0.005 + 4 / 65535.0, 1e-9);
  EXPECT_NEAR(precisionBound(d, 0, 0, 0.5, m), 0.005 + 4 / 65535.0, 1e-12);
  EXPECT_EQ(precisionBound(d, 1, 0, 0.5, exactPrecision()), 0.0);
  const Image plain = covered(2, 1);
  EXPECT_NEAR(precisionBound(plain, 1, 0, 0.5, m), 0.005 + 4 / 65535.0, 1e-12);  // no channels: no probes
  Image other = covered(2, 1);
  other.pixel(1, 0)[0] = 0.01f;
  PrecisionModel one;
  one.position_steps = 1.0;
  // 0.01 > 2 x 0.001 (+ tol 0): unexplained; with 5 steps each, 0.01 <= 0.01.
  EXPECT_EQ(compareImages(other, d, tolerance(0, 1), {one, one}).over_unexplained(), 1);
  one.position_steps = 5.0;
  EXPECT_EQ(compareImages(other, d, tolerance(0, 1), {one, one}).overCount(PixelClass::Precision), 1);
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

TEST(TolerancePasses, AnUnexplainedMaskDisagreementFails) {
  CompareMetrics m;
  m.covered_both = 10;
  m.mask_disagree = 3, m.mask_disagree_explained = 3;
  EXPECT_TRUE(tolerance(0, 1).passes(m));
  m.mask_disagree_explained = 2;
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
  // At the cap it passes; the same pixel with all its samples on an edge
  // passes however large (one sample can turn it from 0 to 1).
  b.pixel(50, 50)[2] = float(cap);
  EXPECT_TRUE(t.passes(compareImages(a, b, t)));
  b.pixel(50, 50)[2] = 1.0f;
  channelAt(a.edge_fraction, a, 50, 50) = 1.0f;
  m = compareImages(a, b, t);
  EXPECT_EQ(m.overCount(PixelClass::Edge), 1);
  EXPECT_EQ(m.max_unexplained, 0.0);
  EXPECT_EQ(m.worst_unexplained_x, -1);
  EXPECT_TRUE(t.passes(m));
  // A pixel within the tolerance is not unexplained.
  b.pixel(10, 10)[0] = float(1.0 / 65535.0);
  EXPECT_EQ(compareImages(a, b, t).max_unexplained, 0.0);
  // Tolerance{} accepts only equal images.
  EXPECT_FALSE(Tolerance{}.passes(compareImages(a, b, Tolerance{})));
}

TEST(CompareImages, MetricsJsonGivesTheCountAndMaxOfEveryClass) {
  Image a = covered(7, 7, true), b = covered(7, 7);
  channelAt(a.edge_fraction, a, 3, 3) = 0.5f;
  b.pixel(3, 3)[0] = 0.5f;
  b.pixel(3, 4)[0] = float(3.0 / 65535.0);
  const nlohmann::json j = metricsJson(compareImages(a, b, tolerance(1.0 / 65535.0, 0.5)));
  for (const PixelClassInfo& c : kPixelClasses) {
    EXPECT_TRUE(j["over_tolerance"].contains(c.key)) << c.key;
    EXPECT_TRUE(j["over_tolerance_max_16bit"].contains(c.key)) << c.key;
  }
  EXPECT_EQ(j["over_tolerance"]["edge"], 1);
  EXPECT_NEAR(j["over_tolerance_max_16bit"]["edge"].get<double>(), 0.5 * 65535.0, 1e-6);
  EXPECT_NEAR(j["max_unexplained_16bit"].get<double>(), 3.0, 1e-3);
  EXPECT_EQ(j["worst_unexplained_pixel"], nlohmann::json::array({3, 4}));
  EXPECT_EQ(j["worst_explained_pixel"], nlohmann::json::array({3, 3}));
}

}  // namespace
}  // namespace xval
