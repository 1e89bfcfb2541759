#include "validate/colour_stats.h"

#include <cmath>
#include <stdexcept>

#include "image/perceptual.h"
#include "shading/models.h"

namespace xval {

ColourStats colourStats(const Image& img) {
  if (img.albedo.empty()) throw std::runtime_error("colour statistics need the reference renderer's albedo channels");
  ColourStats s;
  double chroma = 0, albedo_chroma = 0, hue_err = 0;
  long long grey = 0, hued = 0;
  for (size_t i = 0; i < size_t(img.width) * img.height; ++i) {
    if (img.rgba[i * 4 + 3] <= 0) continue;
    glm::dvec3 c(img.rgba[i * 4], img.rgba[i * 4 + 1], img.rgba[i * 4 + 2]);
    if (models::luma(c) <= 0.02) continue;
    glm::dvec3 a(img.albedo[i * 3], img.albedo[i * 3 + 1], img.albedo[i * 3 + 2]);
    glm::dvec3 lc = srgbToLab(c), la = srgbToLab(a);
    double cc = std::hypot(lc.y, lc.z), ca = std::hypot(la.y, la.z);
    ++s.lit_pixels;
    chroma += cc, albedo_chroma += ca;
    if (cc < 5.0) ++grey;
    if (cc >= 5.0 && ca >= 5.0) {
      double d = std::abs(std::atan2(lc.z, lc.y) - std::atan2(la.z, la.y)) * 180.0 / 3.14159265358979323846;
      if (d > 180.0) d = 360.0 - d;
      hue_err += d, ++hued;
    }
  }
  if (s.lit_pixels) {
    s.mean_chroma = chroma / double(s.lit_pixels);
    s.mean_albedo_chroma = albedo_chroma / double(s.lit_pixels);
    s.grey_fraction = double(grey) / double(s.lit_pixels);
  }
  s.hue_error_deg = hued ? hue_err / double(hued) : 0.0;
  return s;
}

}  // namespace xval
