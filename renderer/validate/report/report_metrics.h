// The report's metrics table of a case: a row per compared pair, a column
// per entry of the metric table (image/metric_table.h: its label, unit and
// better direction), the values from the pair's metrics.values in
// results.json. A pair without values (a results.json written before the
// metric table) shows "n/a"; a null value (not finite) "not finite".
// As data of the page's template (validate/report/report_page.mustache), which
// escapes every string.
#pragma once

#include <kainjow/mustache.hpp>
#include <vector>

#include "validate/results/results.h"

namespace xval {

// The table's columns, one per metric: label, unit (none or one), lower
// (true: lower is better).
kainjow::mustache::data metricColumns();

// `pairs`: a case's pairs (validate/results/results.h). None when no pair
// was compared; else one: metric_rows (pair, values: the cells' texts).
kainjow::mustache::data pairMetricsTable(const std::vector<results::Pair>& pairs);

}  // namespace xval
