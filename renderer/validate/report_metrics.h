// The report's metrics table of a case: a row per compared pair, a column
// per entry of the metric table (image/metric_table.h: its label, unit and
// better direction), the values from the pair's metrics.values in
// results.json. A pair without values (a results.json written before the
// metric table) shows "n/a"; a null value (not finite) "not finite".
#pragma once

#include <string>

#include <vector>

#include "validate/results/results.h"

namespace xval {

// `pairs`: a case's pairs (validate/results/results.h). "" when no pair
// was compared.
std::string pairMetricsTable(const std::vector<results::Pair>& pairs);

}  // namespace xval
