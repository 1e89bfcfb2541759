// A declared bound on one metric of the metric table (image/metric_table.h),
// part of a tolerance (image/compare.h Tolerance; declared in a tolerance
// file's `default` or a scene's `tolerances`, docs/scene-format.md). It
// holds when the pair's value is on the metric's better side of `bound` or
// equal to it: a lower-is-better metric is bounded from above (written
// "max": value <= bound), a higher-is-better one from below ("min": value >=
// bound). A value that is not a number never holds. Here, below both the
// scene data and the images, so that both can hold it; the direction and the
// checks are image/metric_criteria.h's.
#pragma once

#include <string>

namespace xval {

struct MetricCriterion {
  std::string metric;  // an id of the metric table
  double bound = 0;
  bool operator==(const MetricCriterion&) const = default;
};

}  // namespace xval
