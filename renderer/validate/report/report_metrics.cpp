// The report's metrics table (validate/report/report_metrics.h).
#include "validate/report/report_metrics.h"

#include <algorithm>

#include "image/metric_table.h"
#include "text/number_text.h"

namespace xval {

namespace mu = kainjow::mustache;

mu::data metricColumns() {
  mu::data columns(mu::data::type::list);
  for (const MetricInfo& m : metricTable()) {
    mu::data c;
    c.set("label", m.label);
    mu::data unit(mu::data::type::list);
    if (*m.unit) unit << mu::data(m.unit);
    c.set("unit", unit);
    c.set("lower", mu::data(m.better == Better::Lower));
    columns << c;
  }
  return columns;
}

mu::data pairMetricsTable(const std::vector<results::Pair>& pairs) {
  mu::data table(mu::data::type::list), rows(mu::data::type::list);
  for (const results::Pair& p : pairs) {
    if (!p.metrics) continue;
    const results::Named<std::optional<double>> none;
    const auto& values = p.metrics->values ? *p.metrics->values : none;
    mu::data cells(mu::data::type::list);
    for (const MetricInfo& m : metricTable()) {
      const auto v = std::find_if(values.begin(), values.end(), [&](const auto& e) { return e.first == m.id; });
      cells << mu::data(v == values.end() ? std::string("n/a") : !v->second ? "not finite" : significant(*v->second));
    }
    mu::data row;
    row.set("pair", p.pair);
    row.set("values", cells);
    rows << row;
  }
  if (rows.is_empty_list()) return table;
  mu::data t;
  t.set("metric_rows", rows);
  table << t;
  return table;
}

}  // namespace xval
