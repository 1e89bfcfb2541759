// Metric criteria: declared bounds on entries of the metric table
// (scene/metric_criterion.h holds one; image/metric_table.h the table), as
// a tolerance file's `default` and a scene's `tolerances` declare them
// (docs/scene-format.md, "tolerances"):
//   "metrics": {"flip": {"max": 0.05}, "psnr": {"min": 40}}
// Each key an id of the table, its bound under the key of the metric's
// better direction: "max" for a lower-is-better metric, "min" for a
// higher-is-better one (the other key is an error: a "max" on PSNR would
// bound how good a pair may be).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/compare.h"
#include "image/metric_table.h"
#include "scene/json_reader.h"
#include "scene/metric_criterion.h"

namespace xval {

// "max" for a metric whose better direction is Lower, "min" for Higher.
const char* boundKey(const MetricInfo& m);

// The optional object field `key` of r (absent: none), in table order.
// Throws SceneError naming the file and the field: a key that is no id of
// the table (the message lists the ids), a bound under the other
// direction's key (naming the metric, its better direction and the key
// expected, with the value given), a missing or non-numeric bound, any
// other field.
std::vector<MetricCriterion> readMetricCriteria(JsonReader& r, std::string_view key);

// `base` with each metric `declared` names bounded by the declared value
// instead (the others kept), in table order: a scene's declaration over the
// default's.
std::vector<MetricCriterion> overriddenCriteria(const std::vector<MetricCriterion>& base,
                                                const std::vector<MetricCriterion>& declared);

// {id: {"max"|"min": bound}}: the form read above.
nlohmann::json metricCriteriaJson(const std::vector<MetricCriterion>& criteria);

// "flip max 0.05, psnr min 40" ("" for none).
std::string metricCriteriaText(const std::vector<MetricCriterion>& criteria);

// Whether the pair's value of c.metric is on its better side of c.bound or
// equal (a value that is not a number: no). Throws std::runtime_error for
// an id not in the table.
bool metricCriterionHolds(const MetricCriterion& c, const PairMeasures& m);

// The verdict: the pixel criteria (Tolerance::passesPixelCriteria) and
// every metric criterion of t. Empty failedCriteria(m, t) exactly when this
// is true (image/pair_failure.h).
bool passes(const PairMeasures& m, const Tolerance& t);

}  // namespace xval
