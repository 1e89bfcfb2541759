// The report's metrics table (validate/report_metrics.h).
#include "validate/report_metrics.h"

#include <algorithm>
#include <sstream>

#include "image/metric_table.h"
#include "text/number_text.h"
#include "validate/report.h"

namespace xval {

std::string pairMetricsTable(const std::vector<results::Pair>& pairs) {
  std::ostringstream h;
  bool any = false;
  for (const results::Pair& p : pairs) any = any || p.metrics.has_value();
  if (!any) return "";
  h << "<table class=\"metrics\"><tr><th class=\"l\">pair</th>";
  for (const MetricInfo& m : metricTable())
    h << "<th title=\"" << (m.better == Better::Lower ? "lower is better" : "higher is better") << "\">"
      << htmlEscape(m.label) << (*m.unit ? "<br>(" + htmlEscape(m.unit) + ")" : std::string())
      << (m.better == Better::Lower ? " &darr;" : " &uarr;") << "</th>";
  h << "</tr>\n";
  for (const results::Pair& p : pairs) {
    if (!p.metrics) continue;
    h << "<tr><td class=\"l\">" << htmlEscape(p.pair) << "</td>";
    const results::Named<std::optional<double>> none;
    const auto& values = p.metrics->values ? *p.metrics->values : none;
    for (const MetricInfo& m : metricTable()) {
      const auto v = std::find_if(values.begin(), values.end(), [&](const auto& e) { return e.first == m.id; });
      h << "<td>";
      if (v == values.end()) h << "n/a";
      else if (!v->second) h << "not finite";
      else h << significant(*v->second);
      h << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

}  // namespace xval
