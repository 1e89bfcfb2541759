#include "image/compare.h"
#include "image/perceptual.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

namespace xval {

namespace {
bool hit(const Image& img, int x, int y) { return img.pixel(x, y)[3] > 0.0f; }

bool onSilhouette(const Image& img, int x, int y) {
  bool any_hit = false, any_miss = false;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int xx = x + dx, yy = y + dy;
      if (xx < 0 || yy < 0 || xx >= img.width || yy >= img.height) {
        any_miss = true;
        continue;
      }
      (hit(img, xx, yy) ? any_hit : any_miss) = true;
    }
  return any_hit && any_miss;
}

// A depth jump of more than 5% to a neighbour, or a neighbour missed: the
// pixel sits where one surface occludes another.
bool onOcclusionEdge(const Image& img, int x, int y) {
  if (img.depth.empty()) return false;
  const float z = img.depth[size_t(y) * img.width + x];
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int xx = x + dx, yy = y + dy;
      if (xx < 0 || yy < 0 || xx >= img.width || yy >= img.height || !hit(img, xx, yy)) return true;
      if (std::abs(img.depth[size_t(yy) * img.width + xx] - z) > 0.05f * z) return true;
    }
  return false;
}

// Grazing incidence: float rounding of the hit point is amplified by
// 1/|cos|; below 0.1 that is more than ten-fold.
constexpr float kGrazingCos = 0.1f;
bool grazing(const Image& img, int x, int y) {
  return !img.incidence.empty() && img.incidence[size_t(y) * img.width + x] < kGrazingCos;
}

bool backfacing(const Image& img, int x, int y) {
  return !img.backfacing.empty() && img.backfacing[size_t(y) * img.width + x] > 0.0f;
}
}  // namespace

CompareMetrics compareImages(const Image& a, const Image& b, const Tolerance& t) {
  const double tolerance = t.max_abs;
  if (a.width != b.width || a.height != b.height)
    throw std::runtime_error("cannot compare a " + std::to_string(a.width) + "x" +
                             std::to_string(a.height) + " image with a " +
                             std::to_string(b.width) + "x" + std::to_string(b.height) + " one");
  CompareMetrics m;
  m.width = a.width, m.height = a.height;
  m.tolerance = tolerance;
  std::vector<double> errs;
  double sq = 0.0;
  long long within = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      bool ha = hit(a, x, y), hb = hit(b, x, y);
      if (ha != hb) {
        ++m.mask_disagree;
        if (onSilhouette(a, x, y) || onSilhouette(b, x, y)) ++m.mask_disagree_silhouette;
        continue;
      }
      if (!ha) continue;
      const bool bf = backfacing(a, x, y) || backfacing(b, x, y);
      m.backfacing_pixels += bf;
      if (bf && t.exclude_backfacing) continue;
      ++m.covered_both;
      double e = 0.0;
      for (int c = 0; c < 3; ++c) {
        double d = double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c]);
        if (!std::isfinite(d)) d = std::numeric_limits<double>::infinity();
        sq += d * d;
        e = std::max(e, std::abs(d));
      }
      if (e > m.max_abs || m.worst_x < 0) m.max_abs = std::max(m.max_abs, e), m.worst_x = x, m.worst_y = y;
      errs.push_back(e);
      int bin = 0;
      while (bin < 6 && e * 65535.0 > CompareMetrics::kHistogramEdges16[bin]) ++bin;
      ++m.histogram[bin];
      within += e <= tolerance;
      if (e > tolerance) {
        ++m.over_tolerance;
        if (bf) ++m.over_backfacing;
        else if (onOcclusionEdge(a, x, y) || onOcclusionEdge(b, x, y)) ++m.over_occlusion_edge;
        else if (grazing(a, x, y) || grazing(b, x, y)) ++m.over_grazing;
        else ++m.over_unexplained;
      }
    }
  }
  if (m.covered_both > 0) {
    std::sort(errs.begin(), errs.end());
    // Nearest-rank percentile.
    size_t k = size_t(std::ceil(0.999 * double(errs.size()))) - 1;
    m.p999_abs = errs[std::min(k, errs.size() - 1)];
    m.rmse = std::sqrt(sq / (3.0 * double(m.covered_both)));
    m.psnr_db = m.rmse > 0 ? 20.0 * std::log10(1.0 / m.rmse) : std::numeric_limits<double>::infinity();
    m.fraction_within = double(within) / double(m.covered_both);
  }
  return m;
}

Image differenceImage(const Image& a, const Image& b) {
  Image d(a.width, a.height, false);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const float *pa = a.pixel(x, y), *pb = b.pixel(x, y);
      float* pd = d.pixel(x, y);
      for (int c = 0; c < 3; ++c) pd[c] = std::abs(pa[c] - pb[c]);
      pd[3] = (pa[3] > 0 || pb[3] > 0) ? 1.0f : 0.0f;
    }
  return d;
}

std::string toJson(const CompareMetrics& m, const Tolerance& t, const PerceptualMetrics* pm) {
  auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json j = {
      {"width", m.width},
      {"height", m.height},
      {"covered_both", m.covered_both},
      {"mask_disagree", m.mask_disagree},
      {"mask_disagree_silhouette", m.mask_disagree_silhouette},
      {"max_abs", m.max_abs},
      {"max_abs_16bit", m.max_abs * 65535.0},
      {"p999_abs", m.p999_abs},
      {"p999_abs_16bit", m.p999_abs * 65535.0},
      {"rmse", m.rmse},
      {"rmse_16bit", m.rmse * 65535.0},
      {"psnr_db", finite(m.psnr_db)},
      {"fraction_within", m.fraction_within},
      {"worst_pixel", {m.worst_x, m.worst_y}},
      {"backfacing_pixels", m.backfacing_pixels},
      {"over_tolerance", {{"total", m.over_tolerance},
                          {"occlusion_edge", m.over_occlusion_edge},
                          {"backfacing_normal", m.over_backfacing},
                          {"grazing", m.over_grazing},
                          {"unexplained", m.over_unexplained}}},
      {"histogram_16bit", {{"edges", CompareMetrics::kHistogramEdges16},
                           {"counts", m.histogram}}},
      {"tolerance", {{"max_abs_16bit", t.max_abs * 65535.0},
                     {"fraction", t.fraction},
                     {"exclude_backfacing", t.exclude_backfacing}}},
      {"pass", t.passes(m)}};
  if (pm) {
    j["ssim"] = pm->ssim;
    j["ciede2000"] = {{"mean", pm->ciede2000_mean}, {"max", pm->ciede2000_max}};
    j["yiq_delta"] = {{"mean", pm->yiq_mean}, {"max", pm->yiq_max}};
  }
  return j.dump(2);
}

}  // namespace xval
