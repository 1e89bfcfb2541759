// The metric table (image/metric_table.h lists the entries and the rules):
// the entries and their values of a measured pair. Measuring a pair is
// image/pair_measures.cpp, so that a reader of metric ids (a scene's
// declared metric criteria, image/metric_criteria.h) links without the
// measurements.
#include "image/metric_table.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace xval {

const std::vector<MetricInfo>& metricTable() {
  static const std::vector<MetricInfo> table = {
      {"max", "max error", "1/65535", Better::Lower,
       [](const PairMeasures& m) { return m.compare.max_abs * 65535.0; }},
      {"p999", "p99.9 error", "1/65535", Better::Lower,
       [](const PairMeasures& m) { return m.compare.p999_abs * 65535.0; }},
      {"rmse", "RMSE", "1/65535", Better::Lower, [](const PairMeasures& m) { return m.compare.rmse * 65535.0; }},
      {"psnr", "PSNR", "dB", Better::Higher, [](const PairMeasures& m) { return m.compare.psnr_db; }},
      {"ssim", "SSIM", "", Better::Higher, [](const PairMeasures& m) { return m.perceptual.ssim; }},
      {"ciede2000", "mean CIEDE2000", "", Better::Lower,
       [](const PairMeasures& m) { return m.perceptual.ciede2000_mean; }},
      {"ciede2000_max", "max CIEDE2000", "", Better::Lower,
       [](const PairMeasures& m) { return m.perceptual.ciede2000_max; }},
      {"yiq", "mean YIQ delta", "", Better::Lower, [](const PairMeasures& m) { return m.perceptual.yiq_mean; }},
      {"yiq_max", "max YIQ delta", "", Better::Lower, [](const PairMeasures& m) { return m.perceptual.yiq_max; }},
      {"flip", "mean FLIP", "", Better::Lower, [](const PairMeasures& m) { return m.flip.mean; }},
      {"flip_p99", "p99 FLIP", "", Better::Lower, [](const PairMeasures& m) { return m.flip.p99; }},
  };
  return table;
}

std::vector<std::string> metricIds(bool errors_only) {
  std::vector<std::string> ids;
  for (const MetricInfo& m : metricTable())
    if (!errors_only || m.better == Better::Lower) ids.push_back(m.id);
  return ids;
}

std::string joinedIds(const std::vector<std::string>& ids) {
  std::string s;
  for (const std::string& id : ids) s += (s.empty() ? "" : ", ") + id;
  return s;
}

const MetricInfo& metricById(const std::string& id) {
  for (const MetricInfo& m : metricTable())
    if (id == m.id) return m;
  throw std::runtime_error("metric '" + id + "': expected one of " + joinedIds(metricIds()));
}

std::string labelWithUnit(const MetricInfo& m) {
  return std::string(m.label) + (*m.unit ? std::string(" (") + m.unit + ")" : std::string());
}

nlohmann::json metricValuesJson(const PairMeasures& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const MetricInfo& info : metricTable()) {
    const double v = info.value(m);
    j[info.id] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  }
  return j;
}

std::string metricValuesText(const PairMeasures& m) {
  std::string s;
  for (const MetricInfo& info : metricTable()) {
    char v[32];
    std::snprintf(v, sizeof v, "%.6g", info.value(m));
    s += (s.empty() ? "" : ", ") + std::string(info.label) + " " + v + (*info.unit ? std::string(" ") + info.unit : "");
  }
  return s;
}

}  // namespace xval
