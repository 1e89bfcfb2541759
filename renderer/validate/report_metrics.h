// The report's metrics table of a case: a row per compared pair, a column
// per entry of the metric table (image/metric_table.h: its label, unit and
// better direction), the values from the pair's metrics.values in
// results.json. A pair without values (a results.json written before the
// metric table) shows "n/a"; a null value (not finite) "not finite".
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace xval {

// `pairs`: a case's "pairs" array of results.json. "" when no pair was
// compared.
std::string pairMetricsTable(const nlohmann::ordered_json& pairs);

}  // namespace xval
