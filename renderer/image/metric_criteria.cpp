// Metric criteria (image/metric_criteria.h).
#include "image/metric_criteria.h"

#include <algorithm>
#include <cstdio>


namespace xval {

namespace {

// A bound as declared ("%.6g": 40, 0.05), for messages.
std::string boundText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace

const char* boundKey(const MetricInfo& m) { return m.better == Better::Lower ? "max" : "min"; }

std::vector<MetricCriterion> readMetricCriteria(JsonReader& r, std::string_view key) {
  std::vector<MetricCriterion> out;
  auto o = r.object(key);
  if (!o) return out;
  for (const MetricInfo& info : metricTable()) {
    auto c = o->object(info.id);
    if (!c) continue;
    const char* want = boundKey(info);
    const char* other = info.better == Better::Lower ? "min" : "max";
    if (c->has(other)) {
      const double v = c->number(other, 0.0);
      c->fail(other, std::string(info.label) + " is better " + (info.better == Better::Lower ? "lower" : "higher") +
                         ": expected its bound as \"" + want + "\" (the " +
                         (info.better == Better::Lower ? "largest" : "smallest") + " value that passes), got \"" +
                         other + "\": " + boundText(v));
    }
    out.push_back({info.id, c->requireNumber(want)});
    c->finish();
  }
  o->finish();  // a key that is no id of the table: the error lists the ids
  return out;
}

std::vector<MetricCriterion> overriddenCriteria(const std::vector<MetricCriterion>& base,
                                                const std::vector<MetricCriterion>& declared) {
  std::vector<MetricCriterion> out;
  for (const MetricInfo& info : metricTable()) {
    const auto named = [&](const MetricCriterion& c) { return c.metric == info.id; };
    if (auto d = std::find_if(declared.begin(), declared.end(), named); d != declared.end()) out.push_back(*d);
    else if (auto b = std::find_if(base.begin(), base.end(), named); b != base.end()) out.push_back(*b);
  }
  return out;
}

nlohmann::json metricCriteriaJson(const std::vector<MetricCriterion>& criteria) {
  nlohmann::json j = nlohmann::json::object();
  for (const MetricCriterion& c : criteria) j[c.metric] = {{boundKey(metricById(c.metric)), c.bound}};
  return j;
}

std::string metricCriteriaText(const std::vector<MetricCriterion>& criteria) {
  std::string s;
  for (const MetricCriterion& c : criteria)
    s += (s.empty() ? "" : ", ") + c.metric + " " + boundKey(metricById(c.metric)) + " " + boundText(c.bound);
  return s;
}

bool metricCriterionHolds(const MetricCriterion& c, const PairMeasures& m) {
  const MetricInfo& info = metricById(c.metric);
  const double v = info.value(m);
  return info.better == Better::Lower ? v <= c.bound : v >= c.bound;
}

bool passes(const PairMeasures& m, const Tolerance& t) {
  if (!t.passesPixelCriteria(m.compare)) return false;
  for (const MetricCriterion& c : t.metrics)
    if (!metricCriterionHolds(c, m)) return false;
  return true;
}

}  // namespace xval
