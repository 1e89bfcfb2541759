// Comparing two renders of one scene, over the pixels both cover.
//
// hit = alpha > 0. Pixels where exactly one image hits are "mask
// disagreements"; one is explained only where the reference's diagnostics
// say its whole coverage difference is samples within rounding of a
// triangle's boundary (image/pixel_classes.h, the edge bound), any other
// is a real disagreement. Colour metrics use the pixels both images hit; a
// pixel's error is its largest channel difference. Every covered pixel
// over the tolerance is explained by a cause up to the largest difference
// that cause can produce there (pixel_classes.h: precision, edge,
// backfacing normal), or it is unexplained. OpenImageIO's
// ImageBufAlgo::compare has no masks and no percentiles, hence this.
//
// The same errors over the pixels EITHER image hits ("either_covered"):
// the colours are premultiplied by coverage (over black), so a pixel one
// image misses counts with its whole difference; for measurements where
// coverage is part of the error (the speed/accuracy trade-off).
//
// Percentiles are nearest-rank: the p-quantile of n values is the k-th
// smallest, k = ceil(p n) (1-based), so p99.9 of fewer than 1000 values is
// the largest.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "image/pixel_classes.h"
#include "image/precision_bound.h"
#include "scene/metric_criterion.h"

namespace xval {

struct CompareMetrics {
  int width = 0, height = 0;
  long long covered_both = 0;      // pixels both images hit
  long long mask_disagree = 0;     // hit in one image only
  long long mask_disagree_explained = 0;  // ... of those, edge samples explain (pixel_classes.h)
  double max_abs = 0.0;            // over covered_both pixels, largest channel difference
  double p999_abs = 0.0;           // 99.9th percentile of the per-pixel error
  double rmse = 0.0;               // over covered_both pixels and the 3 channels
  double psnr_db = 0.0;            // 20 log10(1 / rmse); infinite when equal
  double fraction_within = 1.0;    // of covered_both pixels within tolerance or explained
  double tolerance = 0.0;          // the per-pixel tolerance used for fraction_within
  int worst_x = -1, worst_y = -1;  // where max_abs is
  // Pixels over the tolerance, by class (image/pixel_classes.h: the
  // explained ones within their bounds):
  long long over_tolerance = 0;
  long long over[kPixelClassCount] = {};   // per class: how many
  double over_max[kPixelClassCount] = {};  // per class: the largest error of those pixels
  long long overCount(PixelClass c) const { return over[size_t(c)]; }
  long long over_unexplained() const { return overCount(PixelClass::Unexplained); }
  // The largest error of a covered pixel neither within the tolerance nor
  // explained (0 when there is none), and where: what the tolerance's
  // max_unexplained caps.
  double max_unexplained = 0.0;
  int worst_unexplained_x = -1, worst_unexplained_y = -1;
  // The largest error of an over-tolerance pixel a class explains, and where.
  double max_explained = 0.0;
  int worst_explained_x = -1, worst_explained_y = -1;
  PixelClass worst_explained_class = PixelClass::Unexplained;  // its class
  // The largest pair precision bound P(p) over the covered pixels (0
  // without the reference's precision channels).
  double max_precision_bound = 0.0;
  long long backfacing_pixels = 0;    // covered pixels with N.V < 0 at some sample
  // Pixels by error in 1/65535: <= 0.5, 1, 2, 4, 16, 256, and above.
  static constexpr double kHistogramEdges16[6] = {0.5, 1, 2, 4, 16, 256};
  long long histogram[7] = {0, 0, 0, 0, 0, 0, 0};
  // Over the pixels either image hits (no backfacing exclusion):
  long long covered_either = 0;
  double max_abs_either = 0.0;   // largest channel difference
  double p999_abs_either = 0.0;  // 99.9th percentile of the per-pixel error
  double rmse_either = 0.0;      // over covered_either pixels and the 3 channels
};

// The nearest-rank p-quantile (0 < p <= 1) of `values` (any order; empty:
// 0). Throws std::invalid_argument for p outside (0, 1].
double nearestRankPercentile(std::vector<double> values, double p);

// A declared tolerance: every covered pixel within max_abs or explained
// by a cause within its bound (image/pixel_classes.h) on at least
// `fraction` of the pixels both images cover, no unexplained pixel over
// max_unexplained (the hard cap: whatever the fraction), and every mask
// disagreement explained: the pixel criteria. With `metrics`, also every
// declared bound on a metric of the table (scene/metric_criterion.h): those
// need the pair's measures (image/metric_table.h), so the verdict with them
// is passes(PairMeasures, Tolerance) there and failedCriteria
// (image/pair_failure.h).
// With exclude_backfacing, pixels whose shading normal faces away from the
// eye are left out of the colour metrics (for a renderer that documents
// turning such normals around); they are still counted.
// Tolerance{} accepts only equal images; the project's default is in a
// tolerance file (validate/tolerances.h says which one).
struct Tolerance {
  double max_abs = 0.0;
  double fraction = 1.0;
  bool exclude_backfacing = false;
  double max_unexplained = 0.0;
  std::vector<MetricCriterion> metrics;  // in metric table order
  bool passesPixelCriteria(const CompareMetrics& m) const {
    return m.fraction_within >= fraction && m.max_unexplained <= max_unexplained &&
           m.mask_disagree == m.mask_disagree_explained && m.covered_both > 0;
  }
  // The verdict from the pixel measures alone: for a tolerance without
  // metric criteria. Throws std::logic_error for one with them (deciding
  // without them would pass what they fail).
  bool passes(const CompareMetrics& m) const {
    requireNoMetricCriteria("Tolerance::passes(CompareMetrics)");
    return passesPixelCriteria(m);
  }
  void requireNoMetricCriteria(const char* who) const {
    if (!metrics.empty())
      throw std::logic_error(std::string(who) + ": the tolerance declares metric criteria; decide with the pair's "
                             "measures (image/metric_table.h passes)");
  }
};

// The two renderers' precision models (image/precision_bound.h), a's and
// b's: a pair's precision bound is the sum of theirs.
struct PairPrecision {
  PrecisionModel a = exactPrecision(), b = exactPrecision();
};

// Throws std::runtime_error when the images differ in size.
// The bounds read the reference's diagnostics from whichever image
// carries them (boundsDiagnostics); without them nothing is explained.
CompareMetrics compareImages(const Image& a, const Image& b, const Tolerance& t, const PairPrecision& p = {});

// "precision 3, edge 1, backfacing normal 0, unexplained 0": the
// over-tolerance pixels of each class, in class order, for console lines.
std::string classCountsText(const CompareMetrics& m);

// The pair's precision bound P(p) = B_a(p) + B_b(p) as an image to look at
// beside |a - b| (the same heat map scale: image/heat_map.h): P in every
// colour channel, alpha = covered by either. An empty image (0 x 0) when
// neither image carries the reference's diagnostics.
Image precisionBoundImage(const Image& a, const Image& b, const PairPrecision& p);

// |a - b| per channel (RGB, alpha = 1 where either hits), for looking at.
Image differenceImage(const Image& a, const Image& b);

// The one JSON form of the metrics record: every field above, errors as
// fractions of full scale and (suffix _16bit) in 1/65535; a value that is
// not finite is null. Keys: width, height, covered_both, mask_disagree,
// mask_disagree_explained, max_abs[_16bit], p999_abs[_16bit],
// rmse[_16bit], psnr_db, fraction_within, worst_pixel [x, y],
// backfacing_pixels, over_tolerance {total, and per class of
// image/pixel_classes.h its count: precision, edge, backfacing_normal,
// unexplained}, over_tolerance_max_16bit {per class its largest error},
// max_precision_bound_16bit, max_unexplained_16bit,
// worst_unexplained_pixel [x, y], max_explained_16bit,
// worst_explained_pixel [x, y] ([-1, -1]: none), histogram_16bit {edges,
// counts}, either_covered {pixels, max_abs_16bit, p999_abs_16bit,
// rmse_16bit}.
nlohmann::json metricsJson(const CompareMetrics& m);

// The tolerance's record: {max_abs_16bit, fraction, exclude_backfacing,
// max_unexplained_16bit} in 1/65535, and "metrics" {id: {"max"|"min":
// bound}} (image/metric_criteria.h) when it declares metric criteria.
nlohmann::json toleranceJson(const Tolerance& t);

struct PerceptualMetrics;
// metricsJson(m) with the verdict: tolerance {max_abs_16bit, fraction,
// exclude_backfacing, max_unexplained_16bit} and pass (t without metric
// criteria: Tolerance::passes; with them image/metric_table.h's pairJson); with `pm`, also ssim, ciede2000 {mean, max}
// and yiq_delta {mean, max}.
std::string toJson(const CompareMetrics& m, const Tolerance& t,
                   const PerceptualMetrics* pm = nullptr);

}  // namespace xval
