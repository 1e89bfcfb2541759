// The metric table: every number xval reports about a pair of images, in
// one list. `xval compare` prints it, results.json stores it per pair
// (metrics.values {id: value}), the report shows a column per entry, the
// JUnit file a property per entry, and `xval tradeoff` takes its axis from
// it. Adding a metric is one entry here (and its computation in
// measurePair when it needs one).
//
// A pair is measured once (PairMeasures: image/compare.h's record, the
// perceptual metrics of image/perceptual.h and FLIP of image/flip.h); each
// entry reads its value from that record. Errors are over the pixels both
// images cover (compare.h); FLIP's summaries over the pixels either covers
// (flip.h). The trade-off measures a pair over the pixels either image
// covers by measuring eitherCovered(a, b) (below), so the same entries
// apply there.
//
// Entries, by id (unit; better):
//   max        largest pixel error (1/65535; lower)
//   p999       99.9th percentile of the pixel error (1/65535; lower)
//   rmse       RMSE over the pixels and 3 channels (1/65535; lower)
//   psnr       PSNR (dB; higher; infinite when equal)
//   ssim       SSIM of the luma (higher; 1 when equal)
//   ciede2000      mean CIEDE2000 (lower)
//   ciede2000_max  largest CIEDE2000 (lower)
//   yiq        mean YIQ delta (lower)
//   yiq_max    largest YIQ delta (lower)
//   flip       mean LDR-FLIP at 67 pixels per degree (lower)
//   flip_p99   99th percentile of LDR-FLIP (lower)
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/compare.h"
#include "image/flip.h"
#include "image/image.h"
#include "image/perceptual.h"

namespace xval {

struct PairMeasures {
  CompareMetrics compare;
  PerceptualMetrics perceptual;
  FlipMetrics flip;
};

enum class Better { Lower, Higher };

struct MetricInfo {
  const char* id;     // stable: JSON keys, CLI values, JUnit property names
  const char* label;  // for people: report headers, plot axes
  const char* unit;   // "" when dimensionless
  Better better;
  double (*value)(const PairMeasures&);
};

const std::vector<MetricInfo>& metricTable();
// Throws std::runtime_error naming the id and listing the table's ids.
const MetricInfo& metricById(const std::string& id);
// "max, p999, ..." (the ids, in table order); with errors_only, only the
// entries whose better direction is Lower (the errors a trade-off
// minimises).
std::vector<std::string> metricIds(bool errors_only = false);
std::string joinedIds(const std::vector<std::string>& ids);
// "RMSE (1/65535)": the label with its unit, if any.
std::string labelWithUnit(const MetricInfo& m);

// What measurePair reads of one image beyond the image, for a caller that
// keeps it for every pair the image is in (validate: n - 1 pairs each).
struct MeasuredImage {
  PerceptualImage perceptual;
  FlipImage flip;
};
MeasuredImage measuredImage(const Image& img);

// Measures the pair once: compareImages(a, b, t, p), perceptualMetrics and
// FLIP (flipErrorMap, flipSummary). ma, mb: a's and b's measuredImage when
// the caller keeps them, else null (computed here); the values are the
// same either way.
PairMeasures measurePair(const Image& a, const Image& b, const Tolerance& t, const PairPrecision& p = {},
                         const MeasuredImage* ma = nullptr, const MeasuredImage* mb = nullptr);

// {id: value} over the table, a value that is not finite as null.
nlohmann::json metricValuesJson(const PairMeasures& m);
// The pair's JSON record: toJson(m.compare, t, &m.perceptual) (compare.h)
// with "values": metricValuesJson(m), the tolerance with its metric
// criteria (toleranceJson) and "pass" on all of them (passes,
// image/metric_criteria.h).
nlohmann::json pairJson(const PairMeasures& m, const Tolerance& t);
// "max 1.5 (1/65535), ..., mean FLIP 0.0123": every entry, for console
// lines; %.6g.
std::string metricValuesText(const PairMeasures& m);

// a and b with the coverage of either (alpha 1 where either covers, else 0)
// and the colours premultiplied as they are (over black), clamped to
// [0, 1]; without diagnostics. Measuring these measures a pair over the
// pixels either covers, a pixel one image misses counting whole.
std::pair<Image, Image> eitherCovered(const Image& a, const Image& b);

}  // namespace xval
