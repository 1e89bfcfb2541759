// Measuring one extremes case (matrix.h says what and why): the reference
// renderer's NaN/Inf pixels and time in one precision, another render
// against the double reference with the one comparison (image/compare.h:
// metrics at the default per-pixel tolerance of 2/65535, whose
// fraction_within is reported, not judged), and its heat map.
#pragma once

#include <filesystem>

#include "image/compare.h"
#include "image/image.h"
#include "scene/scene.h"

namespace xval::extremes {

// Pixels with a non-finite value: in R, G, B or A (final), in raw.R/G/B.
struct NonFinite {
  long long final_pixels = 0;
  long long raw_pixels = 0;
  long long total() const { return final_pixels + raw_pixels; }
};
NonFinite countNonFinite(const Image& img);

// One reference render (diagnostics on, so raw is filled).
struct ReferenceRender {
  Image image;
  NonFinite nonfinite;
  double seconds = 0.0;
};
ReferenceRender renderReference(const Scene& scene, Precision precision, int threads);

// b against a (the double reference): metrics at the default per-pixel
// tolerance of 2/65535 (fraction_within is reported, not judged).
CompareMetrics compareToReference(const Image& reference, const Image& other);

// Heat map of the largest channel difference per pixel (matrix.h), 8-bit
// PNG at the image's own size (its scale bar: image/heat_map.h).
void writeHeatMap(const Image& a, const Image& b, const std::filesystem::path& png);

}  // namespace xval::extremes
