#include "validate/report/junit_report.h"

#include <algorithm>
#include <stdexcept>

#include "image/metric_criteria.h"
#include "image/metric_table.h"
#include "image/pair_failure.h"
#include "validate/results/case_verdict.h"
#include "text/number_text.h"
#include "validate/results/geometry_checks.h"

namespace xval {

std::string xmlEscape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (unsigned char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (c < 0x20 && c != '\t' && c != '\n') out += "\xEF\xBF\xBD";  // U+FFFD
        else out += char(c);
    }
  }
  return out;
}

namespace {

std::string num(double v) { return significant(v); }

// xs:decimal: no exponent.
std::string secondsText(double v) { return fixed(v < 0 ? 0.0 : v, 3); }

// "p99.9 0.55/65535, max 42219.5/65535, 99.9344% within 2/65535 (needs
// 99.9%), 0 mask disagreements no edge explains"
std::string describeMetrics(const results::PairMetrics& m) {
  std::string s = "p99.9 " + num(m.p999_abs_16bit) + "/65535, max " + num(m.max_abs_16bit) + "/65535, " +
                  num(100.0 * m.fraction_within) + "% within " + num(m.tolerance.max_abs_16bit) + "/65535 (needs " +
                  num(100.0 * m.tolerance.fraction) + "%)";
  s += ", " + num(double(m.mask_disagree - m.mask_disagree_explained)) + " mask disagreements no edge explains";
  if (!m.tolerance.metrics.empty()) s += "; declared metric criteria: " + metricCriteriaText(m.tolerance.metrics);
  if (!m.tolerance_reason.empty()) s += "; declared tolerance: " + m.tolerance_reason;
  return s;
}

// A compared pair's metric values (results.json metrics.values: the metric
// table, image/metric_table.h) as testcase properties "metric.ID", in
// table order; "" when it has none (a results.json from before the table).
// A null value (not finite) is "not finite".
std::string metricProperties(const results::Pair& p) {
  if (!p.metrics || !p.metrics->values) return "";
  const auto& values = *p.metrics->values;
  std::string s = "      <properties>\n";
  for (const MetricInfo& m : metricTable()) {
    const auto v = std::find_if(values.begin(), values.end(), [&](const auto& e) { return e.first == m.id; });
    if (v == values.end()) continue;
    s += "        <property name=\"metric." + xmlEscape(m.id) + "\" value=\"" +
         (v->second ? num(*v->second) : std::string("not finite")) + "\"/>\n";
  }
  return s + "      </properties>\n";
}

// "covered 19553, 0 hit/object disagreements off silhouettes (3 on them),
// max depth rel. error 3.3e-06 (bound 2e-05), max uv error 0.84 (bound
// 0.0001), 0 edge pixels over"
std::string describeGeometry(const results::GeometryCheckMetrics& m, const results::GeometryCheckBounds& b) {
  return "covered " + num(double(m.covered)) + ", " + num(double(m.mask_disagree - m.mask_disagree_silhouette)) +
         " hit/object disagreements off silhouettes (" + num(double(m.mask_disagree_silhouette)) +
         " on them), max depth rel. error " + num(m.max_depth_rel) + " (bound " + num(b.max_depth_rel) +
         "), max uv error " + num(m.max_uv) + " (bound " + num(b.max_uv) + "), " + num(double(m.edge_over)) +
         " edge pixels over";
}

double seconds(const results::Case& c, const std::string& id) {
  const results::Render* r = c.render(id);
  return r ? r->seconds : 0.0;
}

std::string renderErrors(const results::Case& c) {
  std::string s;
  for (const auto& [name, r] : c.renders)
    if (r.error) s += name + ": " + *r.error + "\n";
  return s;
}

}  // namespace

std::string junitXml(const results::Results& results, const std::string& suite_name) {
  using results::PairVerdict;
  struct Counts { int tests = 0, failures = 0, errors = 0, skipped = 0; double time = 0; } n;
  std::string body;
  for (const results::Case& c : results.cases) {
    const std::string scene = xmlEscape(c.scene);
    const int errors_before = n.errors;
    for (const results::Pair& p : c.pairs) {
      double t = 0;
      if (auto dash = p.pair.find('-'); dash != std::string::npos)
        t = seconds(c, p.pair.substr(0, dash)) + seconds(c, p.pair.substr(dash + 1));
      ++n.tests;
      n.time += t;
      body += "    <testcase classname=\"" + scene + "\" name=\"" + xmlEscape(p.pair) + "\" time=\"" + secondsText(t) + "\"";
      switch (p.verdict) {
        case PairVerdict::NotExpressible:
          ++n.skipped;
          body += ">\n      <skipped message=\"" + xmlEscape("not expressible: " + p.not_expressible.value_or("")) +
                  "\"/>\n    </testcase>\n";
          break;
        case PairVerdict::Error:
          ++n.errors;
          body += ">\n      <error message=\"" + xmlEscape(p.error.value_or("error")) + "\" type=\"error\">" +
                  xmlEscape(renderErrors(c)) + "</error>\n    </testcase>\n";
          break;
        case PairVerdict::Pass: {
          const std::string props = metricProperties(p);
          body += props.empty() ? "/>\n" : ">\n" + props + "    </testcase>\n";
          break;
        }
        case PairVerdict::Finding:  // passes: the difference the scene declares, measured
          body += ">\n" + metricProperties(p) + "      <system-out>" +
                  xmlEscape("finding of " + p.finding->renderer + ": " + p.finding->why + "; outside the tolerance as "
                            "declared: " + failedText(p.failed) + "; " + describeMetrics(*p.metrics)) +
                  "</system-out>\n    </testcase>\n";
          break;
        case PairVerdict::Fail:  // a compared pair: the reader requires its metrics
          ++n.failures;
          body += ">\n" + metricProperties(p) + "      <failure message=\"" +
                  xmlEscape(p.failed.empty() && p.finding
                                ? "the finding of " + p.finding->renderer + " no longer holds (within the tolerance): " +
                                      p.finding->why + "; " + describeMetrics(*p.metrics)
                                : "outside the tolerance: " + failedText(p.failed) + "; " + describeMetrics(*p.metrics)) +
                  "\" type=\"" + (p.failed.empty() ? "finding_no_longer_holds" : "outside_tolerance") +
                  "\"/>\n    </testcase>\n";
          break;
      }
    }
    // The case's geometry checks (validate/results/geometry_checks.h):
    // one testcase each, "reference-blender-import (geometry)".
    for (const results::GeometryCheck& g : c.geometry_checks) {
      const std::string reason = g.reason.value_or("");
      const double t = seconds(c, g.renderer);
      ++n.tests;
      n.time += t;
      body += "    <testcase classname=\"" + scene + "\" name=\"" +
              xmlEscape(validation::geometryCheckName(g.against, g.renderer)) + "\" time=\"" + secondsText(t) + "\"";
      switch (g.verdict) {
        case PairVerdict::Pass: body += "/>\n"; break;
        case PairVerdict::NotExpressible:
          ++n.skipped;
          body += ">\n      <skipped message=\"" + xmlEscape("not expressible: " + reason) + "\"/>\n    </testcase>\n";
          break;
        case PairVerdict::Error:
          ++n.errors;
          body += ">\n      <error message=\"" + xmlEscape(reason) + "\" type=\"error\">" + xmlEscape(renderErrors(c)) +
                  "</error>\n    </testcase>\n";
          break;
        case PairVerdict::Finding:  // the reader refuses it for a check
        case PairVerdict::Fail:  // a compared check: the reader requires its metrics and bounds
          ++n.failures;
          body += ">\n      <failure message=\"" +
                  xmlEscape("geometry outside its bounds: " + reason + "; " + describeGeometry(*g.metrics, *g.bounds)) +
                  "\" type=\"outside_tolerance\"/>\n    </testcase>\n";
          break;
      }
    }
    // The case's own testcase, when its verdict says what its testcases do not.
    if (!c.verdict) continue;  // a crosscheck's case has none (results/results.h)
    const validation::CaseVerdict v = *c.verdict;
    const bool no_error_testcase = n.errors == errors_before;
    if (v != validation::CaseVerdict::NotCompared && !(v == validation::CaseVerdict::Error && no_error_testcase)) continue;
    ++n.tests;
    body += "    <testcase classname=\"" + scene + "\" name=\"case\" time=\"0.000\">\n";
    if (v == validation::CaseVerdict::Error) {
      ++n.errors;
      body += "      <error message=\"a render failed\" type=\"error\">" + xmlEscape(renderErrors(c)) +
              "</error>\n    </testcase>\n";
      continue;
    }
    ++n.failures;
    std::string why = "nothing compared (no image pair, no geometry check)";
    if (!c.attribution.empty()) why += ": " + c.attribution;
    for (const auto& [id, reason] : c.left_out) why += "; " + id + " left out: " + reason;
    body += "      <failure message=\"" + xmlEscape(why) + "\" type=\"not_compared\"/>\n    </testcase>\n";
  }
  const std::string counts = " tests=\"" + std::to_string(n.tests) + "\" failures=\"" +
                             std::to_string(n.failures) + "\" errors=\"" + std::to_string(n.errors) +
                             "\" skipped=\"" + std::to_string(n.skipped) + "\" time=\"" + secondsText(n.time) + "\"";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"xval\"" + counts + ">\n  <testsuite name=\"" +
         xmlEscape(suite_name) + "\"" + counts + ">\n" + body + "  </testsuite>\n</testsuites>\n";
}

}  // namespace xval
