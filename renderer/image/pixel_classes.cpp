#include "image/pixel_classes.h"

#include <cmath>

namespace xval {

const std::array<PixelClassInfo, kPixelClassCount> kPixelClasses = {{
    {PixelClass::BackfacingNormal, "backfacing_normal", "backfacing normal",
     "the interpolated shading normal faces away from the eye (N.V < 0); POV-Ray turns it around, the paper's "
     "shader uses it as it is",
     "backfacing-normal"},
    {PixelClass::OcclusionEdge, "occlusion_edge", "occlusion edge",
     "one surface occludes another here (a depth jump or a miss next to the pixel): the renderers' intersection "
     "arithmetic moves the edge by a fraction of a pixel",
     "occlusion-edge"},
    {PixelClass::Grazing, "grazing", "grazing incidence",
     "the ray meets its triangle at |cos| < 0.1: float rounding of the hit point is amplified more than ten-fold",
     "grazing-incidence"},
    {PixelClass::TexelBoundary, "texel_boundary", "nearest-texel boundary",
     "the uv lies within the float rounding of a texel edge of a nearest-filtered texture: a renderer may pick "
     "the neighbouring texel",
     "texel-boundary"},
    {PixelClass::TriangleEdge, "triangle_edge", "triangle edge",
     "the ray passes within the rounding of a triangle edge (2^-8 px): another renderer may hit the neighbouring "
     "triangle or pass through a crack between the two",
     "triangle-edge"},
    {PixelClass::Unexplained, "unexplained", "unexplained",
     "none of the known causes: capped by max_unexplained_16bit", "unexplained"},
}};

namespace {

bool hit(const Image& img, int x, int y) { return img.pixel(x, y)[3] > 0.0f; }

float channel(const std::vector<float>& c, const Image& img, int x, int y) {
  return c[size_t(y) * img.width + x];
}

bool backfacing(const Image& img, int x, int y) {
  return !img.backfacing.empty() && channel(img.backfacing, img, x, y) > 0.0f;
}

// A depth jump of more than kDepthJump to a neighbour, or a neighbour
// missed: the pixel sits where one surface occludes another.
bool onOcclusionEdge(const Image& img, int x, int y) {
  if (img.depth.empty()) return false;
  const float z = channel(img.depth, img, x, y);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      int xx = x + dx, yy = y + dy;
      if (xx < 0 || yy < 0 || xx >= img.width || yy >= img.height || !hit(img, xx, yy)) return true;
      if (std::abs(channel(img.depth, img, xx, yy) - z) > kDepthJump * z) return true;
    }
  return false;
}

bool grazing(const Image& img, int x, int y) {
  return !img.incidence.empty() && channel(img.incidence, img, x, y) < kGrazingCos;
}

bool nearTexelEdge(const Image& img, int x, int y) {
  return img.texel_edge.size() == size_t(img.width) * img.height &&
         channel(img.texel_edge, img, x, y) <= kTexelEdgeRoundings;
}

bool nearTriangleEdge(const Image& img, int x, int y) {
  return img.triangle_edge.size() == size_t(img.width) * img.height &&
         channel(img.triangle_edge, img, x, y) <= kTriangleEdgePixels;
}

}  // namespace

PixelClass classifyPixel(const Image& a, const Image& b, int x, int y) {
  if (backfacing(a, x, y) || backfacing(b, x, y)) return PixelClass::BackfacingNormal;
  if (onOcclusionEdge(a, x, y) || onOcclusionEdge(b, x, y)) return PixelClass::OcclusionEdge;
  if (grazing(a, x, y) || grazing(b, x, y)) return PixelClass::Grazing;
  if (nearTexelEdge(a, x, y) || nearTexelEdge(b, x, y)) return PixelClass::TexelBoundary;
  if (nearTriangleEdge(a, x, y) || nearTriangleEdge(b, x, y)) return PixelClass::TriangleEdge;
  return PixelClass::Unexplained;
}

}  // namespace xval
