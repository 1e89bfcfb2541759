// Why a pair fails its tolerance (pair_failure.h).
#include "image/pair_failure.h"

#include <cmath>
#include <cstdlib>

#include "image/metric_criteria.h"
#include "text/number_text.h"

namespace xval {

namespace {

// v with at least `min_digits` decimals, and more (up to 9) until the text
// itself is on the side of `bound` that v is (below: v < bound, else v >
// bound): 99.8999% against 99.9% is "99.8999", never "99.90".
std::string beside(double v, double bound, bool below, int min_digits) {
  std::string s = fixed(v, min_digits);
  for (int d = min_digits; d <= 9 && std::isfinite(v); ++d) {
    s = fixed(v, d);
    const double shown = std::strtod(s.c_str(), nullptr);
    if (below ? shown < bound : shown > bound) break;
  }
  return s;
}

std::string plural(long long n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The pixel criteria's failures.
std::vector<PairFailure> failedPixelCriteria(const CompareMetrics& m, const Tolerance& t) {
  // Each test is the negation of Tolerance::passesPixelCriteria's own
  // comparison, so a NaN fails here exactly when it fails there.
  std::vector<PairFailure> out;
  if (!(m.covered_both > 0)) out.push_back({"nothing_covered", "no pixel covered by both", "nothing covered"});
  if (m.mask_disagree != m.mask_disagree_explained) {
    const long long n = m.mask_disagree - m.mask_disagree_explained;
    out.push_back({"mask", plural(n, "mask disagreement", "mask disagreements") + " no edge explains",
                   plural(n, "mask disagreement", "mask disagreements")});
  }
  if (!(m.max_unexplained <= t.max_unexplained)) {
    const double cap16 = t.max_unexplained * 65535.0;
    const std::string v = beside(m.max_unexplained * 65535.0, cap16, false, 1);
    out.push_back({"unexplained_cap",
                   "unexplained error " + v + "/65535 > cap " + significant(cap16) + "/65535 at (" +
                       std::to_string(m.worst_unexplained_x) + ", " + std::to_string(m.worst_unexplained_y) + ")",
                   "unexplained " + v + " > " + significant(cap16)});
  }
  if (!(m.fraction_within >= t.fraction)) {
    const std::string v = beside(100.0 * m.fraction_within, 100.0 * t.fraction, true, 2) + "%";
    const std::string need = significant(100.0 * t.fraction) + "%";
    // The pixels outside, from the fraction of the covered ones.
    const long long outside =
        std::isfinite(m.fraction_within) ? std::llround((1.0 - m.fraction_within) * double(m.covered_both)) : -1;
    std::string text = "fraction within tolerance " + v + " < " + need;
    if (outside >= 0)
      text += " (" + std::to_string(outside) + " of " + std::to_string(m.covered_both) + " pixels outside)";
    out.push_back({"fraction", text, "fraction " + v + " < " + need});
  }
  return out;
}

}  // namespace

std::vector<PairFailure> failedCriteria(const CompareMetrics& m, const Tolerance& t) {
  t.requireNoMetricCriteria("failedCriteria(CompareMetrics, Tolerance)");
  return failedPixelCriteria(m, t);
}

std::vector<PairFailure> failedCriteria(const PairMeasures& m, const Tolerance& t) {
  std::vector<PairFailure> out = failedPixelCriteria(m.compare, t);
  for (const MetricCriterion& c : t.metrics) {
    if (metricCriterionHolds(c, m)) continue;  // its negation: a NaN fails here as in passes()
    const MetricInfo& info = metricById(c.metric);
    const bool lower = info.better == Better::Lower;
    const std::string unit = *info.unit ? std::string(" ") + info.unit : std::string();
    const std::string v = beside(info.value(m), c.bound, !lower, 3);
    const std::string cmp = lower ? " > " : " < ";
    out.push_back({std::string("metric:") + info.id,
                   std::string(info.label) + " " + v + unit + cmp + boundKey(info) + " " + significant(c.bound) + unit,
                   std::string(info.id) + " " + v + cmp + significant(c.bound)});
  }
  return out;
}

bool failsOnlyOnFraction(const std::vector<PairFailure>& failed) {
  if (failed.empty()) return false;
  for (const PairFailure& f : failed)
    if (f.key != "fraction") return false;
  return true;
}

nlohmann::json failedJson(const std::vector<PairFailure>& failed) {
  nlohmann::json j = nlohmann::json::array();
  for (const PairFailure& f : failed) j.push_back({{"key", f.key}, {"text", f.text}, {"brief", f.brief}});
  return j;
}

std::string failedText(const std::vector<PairFailure>& failed) {
  std::string s;
  for (const PairFailure& f : failed) s += (s.empty() ? "" : "; ") + f.text;
  return s;
}

}  // namespace xval
