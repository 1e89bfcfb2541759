#include "image/heat_map.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace xval {

namespace {

glm::vec3 ramp(double t) {
  static const glm::vec3 stops[] = {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0},
                                    {1, 1, 0}, {1, 0, 0}, {1, 1, 1}};
  t = std::clamp(t, 0.0, 1.0) * 6.0;
  int i = std::min(5, int(t));
  float f = float(t - i);
  return stops[i] * (1.0f - f) + stops[i + 1] * f;
}

double heatT(double err16) {
  if (!(err16 == err16)) return 1.0;  // NaN: the top of the scale
  if (err16 <= kHeatMin16) return err16 / kHeatMin16 * (1.0 / 7.0);  // 0..1 LSB: the first seventh
  return 1.0 / 7.0 + (6.0 / 7.0) * std::log(err16 / kHeatMin16) / std::log(kHeatMax16 / kHeatMin16);
}

}  // namespace

Image heatMap(const Image& d) {
  Image h(d.width, d.height, false);
  for (size_t i = 0; i < size_t(d.width) * d.height; ++i) {
    glm::vec3 c(0.35f);  // covered by neither render
    if (d.rgba[i * 4 + 3] > 0) {
      double e = std::max({d.rgba[i * 4], d.rgba[i * 4 + 1], d.rgba[i * 4 + 2]}) * 65535.0;
      c = ramp(heatT(e));
    }
    for (int k = 0; k < 3; ++k) h.rgba[i * 4 + k] = c[k];
    h.rgba[i * 4 + 3] = 1.0f;
  }
  return h;
}

void writeHeatScalePng(const std::filesystem::path& png) {
  Image s(512, 16, false);
  for (int x = 0; x < 512; ++x) {
    glm::vec3 c = ramp(x / 511.0);
    for (int y = 0; y < 16; ++y) {
      float* p = s.pixel(x, y);
      p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 1.0f;
    }
  }
  writePreviewPng(s, png, 512);
}

}  // namespace xval
