// Measuring a pair of images for the metric table (image/metric_table.h:
// measuredImage, measurePair, pairJson, eitherCovered).
#include <algorithm>
#include <stdexcept>

#include "image/metric_criteria.h"
#include "image/metric_table.h"

namespace xval {

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

nlohmann::json pairJson(const PairMeasures& m, const Tolerance& t) {
  // compare.h's record of the pixel criteria, then the tolerance with its
  // metric criteria and the verdict on all of them.
  Tolerance pixel = t;
  pixel.metrics.clear();
  nlohmann::json j = nlohmann::json::parse(toJson(m.compare, pixel, &m.perceptual));
  j["tolerance"] = toleranceJson(t);
  j["pass"] = passes(m, t);
  j["values"] = metricValuesJson(m);
  return j;
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
