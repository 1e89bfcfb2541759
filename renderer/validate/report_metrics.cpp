// The report's metrics table (validate/report_metrics.h).
#include "validate/report_metrics.h"

#include <sstream>

#include "image/metric_table.h"
#include "validate/common/number_text.h"
#include "validate/report.h"

namespace xval {

std::string pairMetricsTable(const nlohmann::ordered_json& pairs) {
  std::ostringstream h;
  bool any = false;
  for (const auto& p : pairs) any = any || p.contains("metrics");
  if (!any) return "";
  h << "<table class=\"metrics\"><tr><th class=\"l\">pair</th>";
  for (const MetricInfo& m : metricTable())
    h << "<th title=\"" << (m.better == Better::Lower ? "lower is better" : "higher is better") << "\">"
      << htmlEscape(m.label) << (*m.unit ? "<br>(" + htmlEscape(m.unit) + ")" : std::string())
      << (m.better == Better::Lower ? " &darr;" : " &uarr;") << "</th>";
  h << "</tr>\n";
  for (const auto& p : pairs) {
    if (!p.contains("metrics")) continue;
    h << "<tr><td class=\"l\">" << htmlEscape(p.value("pair", std::string())) << "</td>";
    const auto& values = p["metrics"].value("values", nlohmann::ordered_json::object());
    for (const MetricInfo& m : metricTable()) {
      h << "<td>";
      if (!values.contains(m.id)) h << "n/a";
      else if (values[m.id].is_null()) h << "not finite";
      else h << significant(values[m.id]);
      h << "</td>";
    }
    h << "</tr>\n";
  }
  h << "</table>\n";
  return h.str();
}

}  // namespace xval
