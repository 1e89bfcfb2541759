#include "image/compare.h"
#include "image/metric_criteria.h"
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

// The largest colour channel of either image at (x, y): the value a
// relative precision is a share of.
double largerValue(const Image& a, const Image& b, int x, int y) {
  double v = 0.0;
  for (int c = 0; c < 3; ++c) v = std::max({v, double(std::abs(a.pixel(x, y)[c])), double(std::abs(b.pixel(x, y)[c]))});
  return v;
}
}  // namespace

CompareMetrics compareImages(const Image& a, const Image& b, const Tolerance& t, const PairPrecision& pp) {
  const double tolerance = t.max_abs;
  if (a.width != b.width || a.height != b.height)
    throw std::runtime_error("cannot compare a " + std::to_string(a.width) + "x" +
                             std::to_string(a.height) + " image with a " +
                             std::to_string(b.width) + "x" + std::to_string(b.height) + " one");
  const Image* diag = boundsDiagnostics(a, b);
  auto bounds = [&](int x, int y) {
    return diag ? pixelBounds(*diag, x, y, largerValue(a, b, x, y), pp.a, pp.b) : PixelBounds{};
  };
  CompareMetrics m;
  m.width = a.width, m.height = a.height;
  m.tolerance = tolerance;
  std::vector<double> errs, errs_either;
  double sq = 0.0, sq_either = 0.0;
  long long within = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      bool ha = hit(a, x, y), hb = hit(b, x, y);
      if (ha || hb) {
        double e = 0.0;
        for (int c = 0; c < 3; ++c) {
          double d = double(a.pixel(x, y)[c]) - double(b.pixel(x, y)[c]);
          if (!std::isfinite(d)) d = std::numeric_limits<double>::infinity();
          sq_either += d * d;
          e = std::max(e, std::abs(d));
        }
        errs_either.push_back(e);
      }
      const double da = std::abs(double(a.pixel(x, y)[3]) - double(b.pixel(x, y)[3]));
      if (ha != hb) {
        ++m.mask_disagree;
        if (maskDisagreementExplained(da, bounds(x, y))) ++m.mask_disagree_explained;
        continue;
      }
      if (!ha) continue;
      const bool bf = (!a.backfacing.empty() && a.backfacing[size_t(y) * a.width + x] > 0.0f) ||
                      (!b.backfacing.empty() && b.backfacing[size_t(y) * b.width + x] > 0.0f);
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
      const PixelBounds pb = bounds(x, y);
      m.max_precision_bound = std::max(m.max_precision_bound, pb.precision);
      // A coverage difference no edge explains is unexplained whatever the
      // colour does.
      const bool coverage_ok = da <= tolerance + pb.edge;
      if (e <= tolerance && coverage_ok) {
        ++within;
        continue;
      }
      const PixelClass cls = classifyPixel(e, da, tolerance, pb);
      if (cls == PixelClass::Unexplained) {
        if (e > m.max_unexplained || m.worst_unexplained_x < 0)
          m.max_unexplained = e, m.worst_unexplained_x = x, m.worst_unexplained_y = y;
      } else {
        ++within;  // explained: within its bound
      }
      if (e <= tolerance) continue;
      ++m.over_tolerance;
      const size_t k = size_t(cls);
      ++m.over[k];
      m.over_max[k] = std::max(m.over_max[k], e);
      if (cls != PixelClass::Unexplained && (e > m.max_explained || m.worst_explained_x < 0))
        m.max_explained = e, m.worst_explained_x = x, m.worst_explained_y = y, m.worst_explained_class = cls;
    }
  }
  if (!errs_either.empty()) {
    m.covered_either = (long long)errs_either.size();
    m.max_abs_either = *std::max_element(errs_either.begin(), errs_either.end());
    m.p999_abs_either = nearestRankPercentile(std::move(errs_either), 0.999);
    m.rmse_either = std::sqrt(sq_either / (3.0 * double(m.covered_either)));
  }
  if (m.covered_both > 0) {
    m.p999_abs = nearestRankPercentile(std::move(errs), 0.999);
    m.rmse = std::sqrt(sq / (3.0 * double(m.covered_both)));
    m.psnr_db = m.rmse > 0 ? 20.0 * std::log10(1.0 / m.rmse) : std::numeric_limits<double>::infinity();
    m.fraction_within = double(within) / double(m.covered_both);
  }
  return m;
}

double nearestRankPercentile(std::vector<double> v, double p) {
  if (!(p > 0.0 && p <= 1.0))
    throw std::invalid_argument("percentile " + std::to_string(p) + ": expected 0 < p <= 1");
  if (v.empty()) return 0.0;
  const size_t k = std::min(size_t(std::ceil(p * double(v.size()))), v.size()) - 1;  // 0-based rank
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

std::string classCountsText(const CompareMetrics& m) {
  std::string s;
  for (const PixelClassInfo& c : kPixelClasses)
    s += (s.empty() ? "" : ", ") + std::string(c.name) + " " + std::to_string(m.overCount(c.id));
  return s;
}

Image precisionBoundImage(const Image& a, const Image& b, const PairPrecision& pp) {
  const Image* diag = boundsDiagnostics(a, b);
  if (!diag || a.width != b.width || a.height != b.height) return Image();
  Image out(a.width, a.height, false);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      float* px = out.pixel(x, y);
      if (!hit(a, x, y) && !hit(b, x, y)) continue;
      const PixelBounds pb = pixelBounds(*diag, x, y, largerValue(a, b, x, y), pp.a, pp.b);
      px[0] = px[1] = px[2] = float(pb.precision);
      px[3] = 1.0f;
    }
  return out;
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

nlohmann::json metricsJson(const CompareMetrics& m) {
  auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json over = {{"total", m.over_tolerance}}, over_max = nlohmann::json::object();
  for (const PixelClassInfo& c : kPixelClasses) {
    over[c.key] = m.overCount(c.id);
    over_max[c.key] = finite(m.over_max[size_t(c.id)] * 65535.0);
  }
  return {
      {"width", m.width},
      {"height", m.height},
      {"covered_both", m.covered_both},
      {"mask_disagree", m.mask_disagree},
      {"mask_disagree_explained", m.mask_disagree_explained},
      {"max_abs", finite(m.max_abs)},
      {"max_abs_16bit", finite(m.max_abs * 65535.0)},
      {"p999_abs", finite(m.p999_abs)},
      {"p999_abs_16bit", finite(m.p999_abs * 65535.0)},
      {"rmse", finite(m.rmse)},
      {"rmse_16bit", finite(m.rmse * 65535.0)},
      {"psnr_db", finite(m.psnr_db)},
      {"fraction_within", finite(m.fraction_within)},
      {"worst_pixel", {m.worst_x, m.worst_y}},
      {"backfacing_pixels", m.backfacing_pixels},
      {"over_tolerance", over},
      {"over_tolerance_max_16bit", over_max},
      {"max_unexplained_16bit", finite(m.max_unexplained * 65535.0)},
      {"worst_unexplained_pixel", {m.worst_unexplained_x, m.worst_unexplained_y}},
      {"max_explained_16bit", finite(m.max_explained * 65535.0)},
      {"worst_explained_pixel", {m.worst_explained_x, m.worst_explained_y}},
      {"max_precision_bound_16bit", finite(m.max_precision_bound * 65535.0)},
      {"histogram_16bit", {{"edges", CompareMetrics::kHistogramEdges16},
                           {"counts", m.histogram}}},
      {"either_covered", {{"pixels", m.covered_either},
                          {"max_abs_16bit", finite(m.max_abs_either * 65535.0)},
                          {"p999_abs_16bit", finite(m.p999_abs_either * 65535.0)},
                          {"rmse_16bit", finite(m.rmse_either * 65535.0)}}}};
}

nlohmann::json toleranceJson(const Tolerance& t) {
  nlohmann::json j = {{"max_abs_16bit", t.max_abs * 65535.0},
                      {"fraction", t.fraction},
                      {"exclude_backfacing", t.exclude_backfacing},
                      {"max_unexplained_16bit", t.max_unexplained * 65535.0}};
  if (!t.metrics.empty()) j["metrics"] = metricCriteriaJson(t.metrics);
  return j;
}

std::string toJson(const CompareMetrics& m, const Tolerance& t, const PerceptualMetrics* pm) {
  nlohmann::json j = metricsJson(m);
  j["tolerance"] = toleranceJson(t);
  j["pass"] = t.passes(m);
  if (pm) {
    j["ssim"] = pm->ssim;
    j["ciede2000"] = {{"mean", pm->ciede2000_mean}, {"max", pm->ciede2000_max}};
    j["yiq_delta"] = {{"mean", pm->yiq_mean}, {"max", pm->yiq_max}};
  }
  return j.dump(2);
}

}  // namespace xval
