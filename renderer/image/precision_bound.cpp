#include "image/precision_bound.h"

#include <cmath>
#include <nlohmann/json.hpp>

namespace xval {

PrecisionModel float32Precision() {
  // docs/precision-models.md, "A renderer that declares none".
  return {1.0, 1.0, std::ldexp(1.0, -10), 1e-5, 0.0,
          "float32 throughout, like gl's (the default of a renderer file that declares none)"};
}

bool hasPrecisionChannels(const Image& img) {
  const size_t n = size_t(img.width) * img.height;
  return img.precision_position.size() == n && img.precision_uv.size() == n && img.precision_normal.size() == n;
}

double precisionBound(const Image& d, int x, int y, double value, const PrecisionModel& m) {
  double b = m.relative * std::abs(value) + m.quantum_16bit / 65535.0;
  if (!hasPrecisionChannels(d)) return b;
  const size_t at = size_t(y) * d.width + x;
  return b + m.position_steps * d.precision_position[at] + m.uv_steps * d.precision_uv[at] +
         m.normal_steps * d.precision_normal[at];
}

nlohmann::json precisionJson(const PrecisionModel& m) {
  return {{"position_steps", m.position_steps}, {"uv_steps", m.uv_steps},   {"normal_steps", m.normal_steps},
          {"relative", m.relative},             {"quantum_16bit", m.quantum_16bit}, {"basis", m.basis}};
}

}  // namespace xval
