#include "image/pixel_classes.h"

#include <algorithm>

#include "image/precision_bound.h"

namespace xval {

const std::array<PixelClassInfo, kPixelClassCount> kPixelClasses = {{
    {PixelClass::Precision, "precision", "precision",
     "within the two renderers' precision bounds: what their rounding of hit point, uv, normal and arithmetic can "
     "move the value here",
     "precision"},
    {PixelClass::Edge, "edge", "edge",
     "samples within 2^-8 px of a triangle's boundary, which another renderer may give to the other side: each can "
     "move the pixel by 1/n^2 at most",
     "edge"},
    {PixelClass::BackfacingNormal, "backfacing_normal", "backfacing normal",
     "the interpolated shading normal faces away from the eye (N.V < 0); POV-Ray turns it around, the paper's "
     "shader uses it as it is: up to what turning it changes here",
     "backfacing-normal"},
    {PixelClass::Unexplained, "unexplained", "unexplained",
     "beyond every bound: capped by max_unexplained_16bit", "unexplained"},
}};

PixelClass classifyPixel(double e, double da, double tol, const PixelBounds& b) {
  if (!(da <= tol + b.edge)) return PixelClass::Unexplained;  // NaN too
  if (e <= tol + b.precision) return PixelClass::Precision;
  if (!(e <= tol + b.precision + b.edge + b.backfacing)) return PixelClass::Unexplained;
  return b.backfacing > b.edge ? PixelClass::BackfacingNormal : PixelClass::Edge;
}

bool maskDisagreementExplained(double da, const PixelBounds& b) {
  // E is a multiple of 1/n^2 stored in float, as is alpha: a float's
  // rounding of either must not decide.
  return da <= b.edge + 1e-6;
}

namespace {
float at(const std::vector<float>& c, const Image& img, int x, int y) {
  return c.size() == size_t(img.width) * img.height ? c[size_t(y) * img.width + x] : 0.0f;
}
}  // namespace

PixelBounds pixelBounds(const Image& d, int x, int y, double value, const PrecisionModel& a,
                        const PrecisionModel& b) {
  PixelBounds out;
  out.edge = at(d.edge_fraction, d, x, y);
  out.backfacing = at(d.backfacing_flip, d, x, y);
  out.precision = precisionBound(d, x, y, value, a) + precisionBound(d, x, y, value, b);
  return out;
}

const Image* boundsDiagnostics(const Image& a, const Image& b) {
  const size_t n = size_t(a.width) * a.height;
  if (a.edge_fraction.size() == n) return &a;
  if (b.edge_fraction.size() == n) return &b;
  return nullptr;
}

}  // namespace xval
