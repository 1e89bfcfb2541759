#include "image/heat_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace xval {

namespace {

// The ramp's knots, equally spaced over t in [0, 1], interpolated
// linearly between neighbours in float: t clamped to [0, 1], i + f = 6 t
// (i = floor), colour k_i (1 - f) + k_{i+1} f, k_7 = k_6. (The formula of
// OpenImageIO's color_map, which made the heat maps before: the same
// bits.)
constexpr float kRampKnots[] = {0, 0, 0, 0, 0, 1, 0, 1, 1, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 1, 1};
constexpr int kRampKnotCount = 7;

// The ramp's colour at each t, 3 floats each.
std::vector<float> ramp(const std::vector<float>& t) {
  std::vector<float> rgb(t.size() * 3);
  for (size_t i = 0; i < t.size(); ++i) heatRampColour(t[i], &rgb[i * 3]);
  return rgb;
}

}  // namespace

void heatRampColour(float t, float* rgb) {
  constexpr int segments = kRampKnotCount - 1;
  // Clamped so that NaN gives 0 (std::clamp would keep it).
  const float x = (t >= 0.0f ? (t <= 1.0f ? t : 1.0f) : 0.0f) * float(segments);
  const float whole = std::floor(x);
  const int k = int(whole), next = std::min(k + 1, segments);
  const float f = x - whole;
  for (int c = 0; c < 3; ++c) rgb[c] = kRampKnots[k * 3 + c] * (1.0f - f) + kRampKnots[next * 3 + c] * f;
}

namespace {

double heatT(double err16) {
  if (!(err16 == err16)) return 1.0;  // NaN: the top of the scale
  if (err16 <= kHeatMin16) return err16 / kHeatMin16 * (1.0 / 7.0);  // 0..1 LSB: the first seventh
  return 1.0 / 7.0 + (6.0 / 7.0) * std::log(err16 / kHeatMin16) / std::log(kHeatMax16 / kHeatMin16);
}

}  // namespace

Image heatMap(const Image& d) {
  const size_t n = size_t(d.width) * d.height;
  std::vector<float> t(n, 0.0f);
  for (size_t i = 0; i < n; ++i)
    if (d.rgba[i * 4 + 3] > 0)
      t[i] = float(heatT(std::max({d.rgba[i * 4], d.rgba[i * 4 + 1], d.rgba[i * 4 + 2]}) * 65535.0));
  const std::vector<float> rgb = ramp(t);
  Image h(d.width, d.height, false);
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k)  // grey 0.35: covered by neither render
      h.rgba[i * 4 + k] = d.rgba[i * 4 + 3] > 0 ? rgb[i * 3 + k] : 0.35f;
    h.rgba[i * 4 + 3] = 1.0f;
  }
  return h;
}

Image maxDownscaled(const Image& d, int max_side) {
  if (max_side < 1) throw std::invalid_argument("maxDownscaled: max_side " + std::to_string(max_side) + " < 1");
  const int k = (std::max(d.width, d.height) + max_side - 1) / max_side;
  if (k <= 1) return d;
  Image out((d.width + k - 1) / k, (d.height + k - 1) / k, false);
  for (int y = 0; y < d.height; ++y)
    for (int x = 0; x < d.width; ++x) {
      const float* p = d.pixel(x, y);
      float* o = out.pixel(x / k, y / k);
      for (int c = 0; c < 4; ++c)
        if (p[c] > o[c] || p[c] != p[c]) o[c] = p[c];  // NaN wins: it is the top of the scale
    }
  return out;
}

void writeHeatScalePng(const std::filesystem::path& png) {
  const int W = 512, H = 16;
  std::vector<float> t(size_t(W) * H);
  for (size_t i = 0; i < t.size(); ++i) t[i] = float(int(i % W) / double(W - 1));  // left 0, right 1
  const std::vector<float> rgb = ramp(t);
  Image s(W, H, false);
  for (size_t i = 0; i < t.size(); ++i) {
    for (int k = 0; k < 3; ++k) s.rgba[i * 4 + k] = rgb[i * 3 + k];
    s.rgba[i * 4 + 3] = 1.0f;
  }
  writePreviewPng(s, png, W);
}

std::string writeHeatMapPng(const Image& diff, const std::filesystem::path& results_dir, const std::string& rel,
                            int max_side) {
  writePreviewPng(heatMap(maxDownscaled(diff, max_side)), results_dir / rel, max_side);
  return rel;
}

}  // namespace xval
