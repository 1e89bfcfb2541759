// The trade-off sweep, the converged reference, errors and the Pareto
// front (validate/tradeoff/sweep.h documents every parameter and default).
#include "validate/tradeoff/sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <variant>

#include "image/compare.h"
#include "image/perceptual.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"

namespace xval {

bool TradeoffConfig::sameKnobs(const TradeoffConfig& o) const {
  return spp == o.spp && tessellation_factor == o.tessellation_factor && precision == o.precision &&
         shading == o.shading && texture_filter == o.texture_filter;
}

bool validSpp(int n) {
  if (n < 1 || n > 256) return false;
  int r = int(std::lround(std::sqrt(double(n))));
  return r * r == n;
}

bool hasTessellatedShapes(const Scene& scene) {
  for (const SceneObject& o : scene.objects)
    if (std::holds_alternative<TorusKnot>(o.shape) || std::holds_alternative<UvSphere>(o.shape)) return true;
  return false;
}

TradeoffConfig baseConfig(const Scene& scene) {
  TradeoffConfig c;
  c.id = "base";
  c.group = "base";
  c.spp = scene.render.spp;
  c.tessellation_factor = 1.0;
  c.precision = scene.render.precision;
  c.shading = scene.shading;
  if (scene.material.texture) c.texture_filter = scene.material.texture->filter;
  return c;
}

TradeoffConfig convergedConfig(const Scene& scene, const SweepSettings& s) {
  if (!validSpp(s.reference_spp))
    throw std::runtime_error("reference spp " + std::to_string(s.reference_spp) +
                             ": expected a perfect square in [1, 256]");
  if (!(s.reference_tessellation > 0.0) || !std::isfinite(s.reference_tessellation))
    throw std::runtime_error("reference tessellation factor " + std::to_string(s.reference_tessellation) +
                             ": expected a finite number > 0");
  TradeoffConfig c;
  c.id = "converged";
  c.group = "converged";
  c.spp = s.reference_spp;
  c.tessellation_factor = hasTessellatedShapes(scene) ? s.reference_tessellation : 1.0;
  c.precision = Precision::Double;
  c.shading = ShadingMode::Phong;
  if (scene.material.texture) c.texture_filter = TextureFilter::Bilinear;
  return c;
}

std::vector<TradeoffConfig> sweepConfigs(const Scene& scene, const SweepSettings& s) {
  const TradeoffConfig base = baseConfig(scene);
  std::vector<TradeoffConfig> out{base};
  auto add = [&](TradeoffConfig c) {
    for (const auto& o : out)
      if (o.sameKnobs(c)) return;
    out.push_back(std::move(c));
  };
  auto fmtFactor = [](double f) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", f);
    return std::string(b);
  };
  for (int spp : {1, 4, 16, 64}) {
    if (spp == 64 && s.quick) continue;
    TradeoffConfig c = base;
    c.id = "spp=" + std::to_string(spp), c.group = "spp", c.spp = spp;
    add(c);
  }
  if (hasTessellatedShapes(scene))
    for (double f : {0.25, 0.5, 2.0}) {
      if (f > 1.0 && s.quick) continue;
      TradeoffConfig c = base;
      c.id = "tess=" + fmtFactor(f), c.group = "tessellation", c.tessellation_factor = f;
      add(c);
    }
  {
    TradeoffConfig c = base;
    c.precision = base.precision == Precision::Double ? Precision::Float : Precision::Double;
    c.id = std::string("precision=") + toString(c.precision), c.group = "precision";
    add(c);
  }
  for (ShadingMode m : {ShadingMode::Flat, ShadingMode::Gouraud, ShadingMode::Phong}) {
    if (m == base.shading) continue;
    TradeoffConfig c = base;
    c.shading = m, c.id = std::string("shading=") + toString(m), c.group = "shading";
    add(c);
  }
  if (base.texture_filter) {
    TradeoffConfig c = base;
    c.texture_filter =
        *base.texture_filter == TextureFilter::Bilinear ? TextureFilter::Nearest : TextureFilter::Bilinear;
    c.id = std::string("filter=") + toString(*c.texture_filter), c.group = "filter";
    add(c);
  }
  const bool tess = hasTessellatedShapes(scene);
  {
    TradeoffConfig c = base;
    c.id = "corner:fast", c.group = "corner";
    c.precision = Precision::Float, c.spp = 1;
    if (tess) c.tessellation_factor = 0.5;
    if (c.texture_filter) c.texture_filter = TextureFilter::Nearest;
    add(c);
    c.id = "corner:fast-gouraud", c.shading = ShadingMode::Gouraud;
    add(c);
  }
  for (int spp : {4, 16}) {
    TradeoffConfig c = base;
    c.id = "corner:float-" + std::to_string(spp) + "spp", c.group = "corner";
    c.precision = Precision::Float, c.spp = spp;
    add(c);
  }
  if (!s.quick) {
    TradeoffConfig c = base;
    c.id = "corner:accurate", c.group = "corner";
    c.precision = Precision::Double, c.spp = 16, c.shading = ShadingMode::Phong;
    if (tess) c.tessellation_factor = 2.0;
    if (c.texture_filter) c.texture_filter = TextureFilter::Bilinear;
    add(c);
  }
  // The converged configuration is always its own row (even when an
  // earlier row has the same knobs): its error is the determinism check.
  out.push_back(convergedConfig(scene, s));
  return out;
}

std::vector<TradeoffConfig> convergenceChecks(const Scene& scene, const SweepSettings& s) {
  const TradeoffConfig ref = convergedConfig(scene, s);
  std::vector<TradeoffConfig> out;
  if (hasTessellatedShapes(scene)) {
    TradeoffConfig c = ref;
    c.id = "check:tess-x2", c.group = "check";
    c.tessellation_factor = ref.tessellation_factor * 2.0;
    out.push_back(c);
  }
  const int n = int(std::lround(std::sqrt(double(ref.spp))));
  const int finer = std::min(256, 4 * n * n);
  if (finer > ref.spp) {
    TradeoffConfig c = ref;
    c.id = "check:spp=" + std::to_string(finer), c.group = "check";
    c.spp = finer;
    out.push_back(c);
  }
  return out;
}

int scaledSegments(int segments, double factor, int minimum) {
  const double v = std::round(double(segments) * factor);
  if (!(v < 2147483647.0)) return 2147483647;  // the loader refuses it, with the field
  return std::max(minimum, int(v));
}

Scene applyConfig(const Scene& scene, const TradeoffConfig& c, const Budget& budget) {
  Scene s = scene;
  s.render.spp = c.spp;
  s.render.precision = c.precision;
  s.shading = c.shading;
  if (s.material.texture && c.texture_filter) s.material.texture->filter = *c.texture_filter;
  if (c.tessellation_factor != 1.0)
    for (SceneObject& object : s.objects) {
      Shape& shape = object.shape;
      if (auto* k = std::get_if<TorusKnot>(&shape)) {
        k->segments_along = scaledSegments(k->segments_along, c.tessellation_factor, 3);
        k->segments_around = scaledSegments(k->segments_around, c.tessellation_factor, 3);
      } else if (auto* u = std::get_if<UvSphere>(&shape)) {
        u->segments_longitude = scaledSegments(u->segments_longitude, c.tessellation_factor, 3);
        u->segments_latitude = scaledSegments(u->segments_latitude, c.tessellation_factor, 2);
      }
    }
  // Validate the result as a scene file would be (mesh limits, ...); the
  // message names the scene, this configuration, the field and the value.
  const std::string label = scene.source_file.string() + " [tradeoff " + c.id + "]";
  Scene checked = parseScene(sceneToJson(s).dump(), label, budget);
  checked.source_file = scene.source_file;
  return checked;
}

TradeoffError tradeoffError(const Image& img, const Image& ref) {
  if (img.width != ref.width || img.height != ref.height)
    throw std::runtime_error("tradeoff error: image sizes differ (" + std::to_string(img.width) + "x" +
                             std::to_string(img.height) + " vs " + std::to_string(ref.width) + "x" +
                             std::to_string(ref.height) + ")");
  // The pair measured once (image/metric_table.h) over the pixels either
  // image covers: both images given the coverage of either.
  const auto [ei, er] = eitherCovered(img, ref);
  const PairMeasures pm = measurePair(ei, er, Tolerance{});
  TradeoffError e;
  e.pixels = pm.compare.covered_both;
  if (e.pixels == 0) return e;
  for (const MetricInfo& m : metricTable()) e.metrics[m.id] = m.value(pm);
  e.max_16bit = e.metrics.at("max");
  e.p999_16bit = e.metrics.at("p999");
  e.rmse_16bit = e.metrics.at("rmse");
  e.ciede2000_mean = e.metrics.at("ciede2000");
  e.ciede2000_max = e.metrics.at("ciede2000_max");
  return e;
}

const MetricInfo& tradeoffAxis(const std::string& m) {
  const std::vector<std::string> errors = metricIds(true);
  if (std::find(errors.begin(), errors.end(), m) == errors.end())
    throw std::runtime_error("error metric '" + m + "': expected one of " + joinedIds(errors));
  return metricById(m);
}

double errorMetric(const TradeoffError& e, const std::string& m) {
  tradeoffAxis(m);
  if (auto it = e.metrics.find(m); it != e.metrics.end()) return it->second;
  // A record read from a tradeoff.json without "metrics" has its named fields.
  if (m == "rmse") return e.rmse_16bit;
  if (m == "p999") return e.p999_16bit;
  if (m == "max") return e.max_16bit;
  if (m == "ciede2000") return e.ciede2000_mean;
  if (m == "ciede2000_max") return e.ciede2000_max;
  throw std::runtime_error("error metric '" + m + "': this trade-off record has no value for it");
}

std::vector<size_t> paretoFront(const std::vector<ParetoPoint>& pts, double tol) {
  if (!(tol >= 0.0) || !std::isfinite(tol))
    throw std::runtime_error("Pareto error tolerance " + std::to_string(tol) + ": expected a finite number >= 0");
  auto finite = [](const ParetoPoint& p) { return std::isfinite(p.seconds) && std::isfinite(p.error); };
  std::vector<size_t> front;
  for (size_t i = 0; i < pts.size(); ++i) {
    if (!finite(pts[i])) continue;
    bool dominated = false;
    for (size_t j = 0; j < pts.size() && !dominated; ++j) {
      if (j == i || !finite(pts[j])) continue;
      const ParetoPoint &a = pts[j], &b = pts[i];
      dominated = a.seconds <= b.seconds && a.error <= b.error + tol &&
                  (a.seconds < b.seconds || a.error < b.error - tol);
    }
    if (!dominated) front.push_back(i);
  }
  std::sort(front.begin(), front.end(), [&](size_t a, size_t b) {
    if (pts[a].seconds != pts[b].seconds) return pts[a].seconds < pts[b].seconds;
    if (pts[a].error != pts[b].error) return pts[a].error < pts[b].error;
    return a < b;
  });
  return front;
}

}  // namespace xval
