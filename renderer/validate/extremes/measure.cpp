// Measuring one extremes case (validate/extremes/measure.h).
#include "validate/extremes/measure.h"
#include "validate/tolerances.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "image/heat_map.h"
#include "render/renderer.h"

namespace xval::extremes {

NonFinite countNonFinite(const Image& img) {
  NonFinite n;
  const size_t pixels = size_t(img.width) * img.height;
  for (size_t i = 0; i < pixels; ++i) {
    bool bad = false;
    for (int k = 0; k < 4; ++k) bad |= !std::isfinite(img.rgba[i * 4 + k]);
    n.final_pixels += bad;
    if (img.raw.size() == pixels * 3) {
      bool bad_raw = false;
      for (int k = 0; k < 3; ++k) bad_raw |= !std::isfinite(img.raw[i * 3 + k]);
      n.raw_pixels += bad_raw;
    }
  }
  return n;
}

ReferenceRender renderReference(const Scene& scene, Precision precision, int threads) {
  RenderOptions o = defaultOptions(scene);
  o.precision = precision;
  o.threads = threads;
  o.diagnostics = true;
  const auto t0 = std::chrono::steady_clock::now();
  ReferenceRender r;
  r.image = renderScene(scene, o);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.nonfinite = countNonFinite(r.image);
  return r;
}

CompareMetrics compareToReference(const Image& reference, const Image& other) {
  // The default of the tolerance file found as for a command without a
  // scene (validate/tolerances.h): 2/65535 on 99.9% (fraction_within).
  static const Tolerance t = loadTolerances(findToleranceFile({}, {}).path).default_tolerance;
  return compareImages(reference, other, t);
}

void writeHeatMap(const Image& a, const Image& b, const std::filesystem::path& png) {
  Image d = differenceImage(a, b);
  writePreviewPng(heatMap(d), png, std::max(d.width, d.height));
}

}  // namespace xval::extremes
