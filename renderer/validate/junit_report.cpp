#include "validate/junit_report.h"

#include <cstdio>
#include <stdexcept>

#include "image/metric_table.h"
#include "image/pair_failure.h"
#include "validate/validation/case_verdict.h"
#include "validate/common/number_text.h"
#include "validate/validation/geometry_checks.h"

namespace xval {

using J = nlohmann::json;

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

const J& field(const J& j, const char* key, const std::string& where) {
  if (!j.is_object() || !j.contains(key))
    throw std::runtime_error(where + ": no \"" + key + "\" field");
  return j.at(key);
}

// "p99.9 0.55/65535, max 42219.5/65535, 99.9344% within 2/65535 (needs
// 99.9%), 0 mask disagreements no edge explains"
std::string describeMetrics(const J& m) {
  std::string s;
  auto get = [&m](const char* k) { return m.contains(k) && m[k].is_number() ? m[k].get<double>() : 0.0; };
  s += "p99.9 " + num(get("p999_abs_16bit")) + "/65535, max " + num(get("max_abs_16bit")) +
       "/65535, " + num(100.0 * get("fraction_within")) + "% within ";
  if (m.contains("tolerance") && m["tolerance"].is_object()) {
    const J& t = m["tolerance"];
    s += num(t.value("max_abs_16bit", 0.0)) + "/65535 (needs " + num(100.0 * t.value("fraction", 0.0)) +
         "%)";
  } else {
    s += "the tolerance";
  }
  const double off = get("mask_disagree") - get("mask_disagree_explained");
  s += ", " + num(off) + " mask disagreements no edge explains";
  if (m.contains("tolerance_reason") && m["tolerance_reason"].is_string() &&
      !m["tolerance_reason"].get<std::string>().empty())
    s += "; declared tolerance: " + m["tolerance_reason"].get<std::string>();
  return s;
}

// A compared pair's metric values (results.json metrics.values: the metric
// table, image/metric_table.h) as testcase properties "metric.ID", in
// table order; "" when it has none (a results.json from before the table).
// A null value (not finite) is "not finite".
std::string metricProperties(const J& jp) {
  if (!jp.contains("metrics") || !jp["metrics"].is_object() || !jp["metrics"].contains("values") ||
      !jp["metrics"]["values"].is_object())
    return "";
  const J& values = jp["metrics"]["values"];
  std::string s = "      <properties>\n";
  for (const MetricInfo& m : metricTable()) {
    if (!values.contains(m.id)) continue;
    const J& v = values[m.id];
    s += "        <property name=\"metric." + xmlEscape(m.id) + "\" value=\"" +
         (v.is_number() ? num(v.get<double>()) : std::string("not finite")) + "\"/>\n";
  }
  return s + "      </properties>\n";
}

// "covered 19553, 0 hit/object disagreements off silhouettes (3 on them),
// max depth rel. error 3.3e-06 (bound 2e-05), max uv error 0.84 (bound
// 0.0001), 0 edge pixels over"
std::string describeGeometry(const J& m, const J& b) {
  auto get = [](const J& j, const char* k) { return j.contains(k) && j[k].is_number() ? j[k].get<double>() : 0.0; };
  return "covered " + num(get(m, "covered")) + ", " + num(get(m, "mask_disagree") - get(m, "mask_disagree_silhouette")) +
         " hit/object disagreements off silhouettes (" + num(get(m, "mask_disagree_silhouette")) +
         " on them), max depth rel. error " + num(get(m, "max_depth_rel")) + " (bound " + num(get(b, "max_depth_rel")) +
         "), max uv error " + num(get(m, "max_uv")) + " (bound " + num(get(b, "max_uv")) + "), " +
         num(get(m, "edge_over")) + " edge pixels over";
}

double seconds(const J& renders, const std::string& name) {
  if (!renders.is_object() || !renders.contains(name)) return 0.0;
  const J& r = renders[name];
  return r.is_object() && r.contains("seconds") && r["seconds"].is_number() ? r["seconds"].get<double>()
                                                                            : 0.0;
}

std::string renderErrors(const J& renders) {
  std::string s;
  if (!renders.is_object()) return s;
  for (const auto& [name, r] : renders.items())
    if (r.is_object() && r.contains("error") && r["error"].is_string())
      s += name + ": " + r["error"].get<std::string>() + "\n";
  return s;
}

}  // namespace

std::string junitXml(const J& results, const std::string& suite_name) {
  const J& cases = field(results, "cases", "results");
  if (!cases.is_array()) throw std::runtime_error("results: \"cases\" is not an array");
  struct Counts { int tests = 0, failures = 0, errors = 0, skipped = 0; double time = 0; } n;
  std::string body;
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string where = "results: cases[" + std::to_string(i) + "]";
    const J& c = cases[i];
    const J& scene = field(c, "scene", where);
    const J& pairs = field(c, "pairs", where);
    if (!scene.is_string() || !pairs.is_array())
      throw std::runtime_error(where + ": \"scene\" must be a string and \"pairs\" an array");
    const J renders = c.value("renders", J::object());
    const int errors_before = n.errors;
    for (size_t p = 0; p < pairs.size(); ++p) {
      const J& jp = pairs[p];
      const std::string pw = where + ".pairs[" + std::to_string(p) + "]";
      const J& pair = field(jp, "pair", pw);
      if (!pair.is_string()) throw std::runtime_error(pw + ": \"pair\" must be a string");
      const std::string name = pair.get<std::string>();
      double t = 0;
      if (auto dash = name.find('-'); dash != std::string::npos)
        t = seconds(renders, name.substr(0, dash)) + seconds(renders, name.substr(dash + 1));
      ++n.tests;
      n.time += t;
      body += "    <testcase classname=\"" + xmlEscape(scene.get<std::string>()) + "\" name=\"" +
              xmlEscape(name) + "\" time=\"" + secondsText(t) + "\"";
      if (jp.contains("not_expressible")) {
        ++n.skipped;
        const std::string why = jp["not_expressible"].is_string() ? jp["not_expressible"].get<std::string>()
                                                                  : std::string("not expressible");
        body += ">\n      <skipped message=\"" + xmlEscape("not expressible: " + why) + "\"/>\n    </testcase>\n";
      } else if (jp.contains("error")) {
        ++n.errors;
        const std::string e = jp["error"].is_string() ? jp["error"].get<std::string>() : "error";
        body += ">\n      <error message=\"" + xmlEscape(e) + "\" type=\"error\">" +
                xmlEscape(renderErrors(renders)) + "</error>\n    </testcase>\n";
      } else if (jp.contains("pass") && jp["pass"] == true) {
        const std::string props = metricProperties(jp);
        body += props.empty() ? "/>\n" : ">\n" + props + "    </testcase>\n";
      } else if (jp.contains("pass") && jp["pass"] == false && jp.contains("metrics")) {
        ++n.failures;
        body += ">\n" + metricProperties(jp) + "      <failure message=\"" +
                xmlEscape("outside the tolerance: " + failedText(failedFromJson(field(jp, "failed", pw), pw + ".failed")) +
                          "; " + describeMetrics(jp["metrics"])) +
                "\" type=\"outside_tolerance\"/>\n    </testcase>\n";
      } else {
        throw std::runtime_error(pw + ": neither \"pass\" (with \"metrics\"), \"error\" nor \"not_expressible\"");
      }
    }
    // The case's geometry checks (validate/validation/geometry_checks.h):
    // one testcase each, "reference-blender-import (geometry)".
    const J checks = c.value("geometry_checks", J::array());
    for (size_t g = 0; g < checks.size(); ++g) {
      const J& jg = checks[g];
      const std::string gw = where + ".geometry_checks[" + std::to_string(g) + "]";
      const J& renderer = field(jg, "renderer", gw);
      const J& against = field(jg, "against", gw);
      const J& verdict = field(jg, "verdict", gw);
      if (!renderer.is_string() || !against.is_string() || !verdict.is_string())
        throw std::runtime_error(gw + ": \"renderer\", \"against\" and \"verdict\" must be strings");
      const std::string v = verdict.get<std::string>();
      const std::string reason = jg.contains("reason") && jg["reason"].is_string() ? jg["reason"].get<std::string>() : "";
      const double t = seconds(renders, renderer.get<std::string>());
      ++n.tests;
      n.time += t;
      body += "    <testcase classname=\"" + xmlEscape(scene.get<std::string>()) + "\" name=\"" +
              xmlEscape(validation::geometryCheckName(against.get<std::string>(), renderer.get<std::string>())) +
              "\" time=\"" + secondsText(t) + "\"";
      if (v == "pass") {
        body += "/>\n";
      } else if (v == "not_expressible") {
        ++n.skipped;
        body += ">\n      <skipped message=\"" + xmlEscape("not expressible: " + reason) + "\"/>\n    </testcase>\n";
      } else if (v == "error") {
        ++n.errors;
        body += ">\n      <error message=\"" + xmlEscape(reason) + "\" type=\"error\">" + xmlEscape(renderErrors(renders)) +
                "</error>\n    </testcase>\n";
      } else if (v == "fail" && jg.contains("metrics")) {
        ++n.failures;
        body += ">\n      <failure message=\"" + xmlEscape("geometry outside its bounds: " + reason + "; " +
                                                          describeGeometry(jg["metrics"], jg.value("bounds", J::object()))) +
                "\" type=\"outside_tolerance\"/>\n    </testcase>\n";
      } else {
        throw std::runtime_error(gw + ": verdict \"" + v + "\": expected pass, fail (with \"metrics\"), error or not_expressible");
      }
    }
    // The case's own testcase, when its verdict says what its testcases do not.
    if (!c.contains("verdict")) continue;
    const J& verdict = c["verdict"];
    if (!verdict.is_string()) throw std::runtime_error(where + ": \"verdict\" must be a string");
    const validation::CaseVerdict v = validation::parseCaseVerdict(verdict.get<std::string>(), where + ".verdict");
    const bool no_error_testcase = n.errors == errors_before;
    if (v != validation::CaseVerdict::NotCompared && !(v == validation::CaseVerdict::Error && no_error_testcase)) continue;
    ++n.tests;
    body += "    <testcase classname=\"" + xmlEscape(scene.get<std::string>()) + "\" name=\"case\" time=\"0.000\">\n";
    if (v == validation::CaseVerdict::Error) {
      ++n.errors;
      body += "      <error message=\"a render failed\" type=\"error\">" + xmlEscape(renderErrors(renders)) +
              "</error>\n    </testcase>\n";
      continue;
    }
    ++n.failures;
    std::string why = "nothing compared (no image pair, no geometry check)";
    if (c.contains("attribution") && c["attribution"].is_string()) why += ": " + c["attribution"].get<std::string>();
    if (c.contains("left_out") && c["left_out"].is_object())
      for (const auto& [id, reason] : c["left_out"].items())
        if (reason.is_string()) why += "; " + id + " left out: " + reason.get<std::string>();
    body += "      <failure message=\"" + xmlEscape(why) + "\" type=\"not_compared\"/>\n    </testcase>\n";
  }
  const std::string counts = " tests=\"" + std::to_string(n.tests) + "\" failures=\"" +
                             std::to_string(n.failures) + "\" errors=\"" + std::to_string(n.errors) +
                             "\" skipped=\"" + std::to_string(n.skipped) + "\" time=\"" + secondsText(n.time) + "\"";
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"xval\"" + counts + ">\n  <testsuite name=\"" +
         xmlEscape(suite_name) + "\"" + counts + ">\n" + body + "  </testsuite>\n</testsuites>\n";
}

}  // namespace xval
