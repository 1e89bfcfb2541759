// The metric table (image/metric_table.h lists the entries and the rules).
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

MeasuredImage measuredImage(const Image& img) { return {perceptualImage(img), flipImage(img)}; }

PairMeasures measurePair(const Image& a, const Image& b, const Tolerance& t, const PairPrecision& p,
                         const MeasuredImage* ma, const MeasuredImage* mb) {
  PairMeasures m;
  m.compare = compareImages(a, b, t, p);  // first: it refuses images of different sizes
  if (ma && mb) {
    m.perceptual = perceptualMetrics(a, ma->perceptual, b, mb->perceptual);
    m.flip = flipSummary(flipErrorMap(ma->flip, mb->flip), a, b);
  } else {
    m.perceptual = perceptualMetrics(a, b);
    m.flip = flipMetrics(a, b);
  }
  return m;
}

nlohmann::json metricValuesJson(const PairMeasures& m) {
  nlohmann::json j = nlohmann::json::object();
  for (const MetricInfo& info : metricTable()) {
    const double v = info.value(m);
    j[info.id] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  }
  return j;
}

nlohmann::json pairJson(const PairMeasures& m, const Tolerance& t) {
  nlohmann::json j = nlohmann::json::parse(toJson(m.compare, t, &m.perceptual));
  j["values"] = metricValuesJson(m);
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

std::pair<Image, Image> eitherCovered(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::runtime_error("image sizes differ (" + std::to_string(a.width) + "x" + std::to_string(a.height) +
                             " vs " + std::to_string(b.width) + "x" + std::to_string(b.height) + ")");
  Image ea(a.width, a.height, false), eb(b.width, b.height, false);
  const size_t n = size_t(a.width) * a.height;
  for (size_t i = 0; i < n; ++i) {
    const float alpha = a.rgba[i * 4 + 3] > 0.0f || b.rgba[i * 4 + 3] > 0.0f ? 1.0f : 0.0f;
    for (int c = 0; c < 3; ++c) {
      ea.rgba[i * 4 + c] = std::clamp(a.rgba[i * 4 + c], 0.0f, 1.0f);
      eb.rgba[i * 4 + c] = std::clamp(b.rgba[i * 4 + c], 0.0f, 1.0f);
    }
    ea.rgba[i * 4 + 3] = eb.rgba[i * 4 + 3] = alpha;
  }
  return {std::move(ea), std::move(eb)};
}

}  // namespace xval
