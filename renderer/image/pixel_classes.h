// Why two renders of one scene may differ at a pixel: the known causes,
// each a documented difference between the renderers' arithmetic
// (docs/pixel-classes.md), recognised from the reference renderer's
// diagnostics channels (image/image.h). A pixel no cause explains is
// "unexplained": its error is capped by the tolerance's
// max_unexplained_16bit (image/compare.h).
//
// A pixel's class is the first that applies, in this order:
//   backfacing_normal  a sample's shading normal faces away from the eye
//                      (N.V < 0)
//   occlusion_edge     a neighbour (3x3) is missed or lies more than 5%
//                      nearer or farther (a depth jump); the image border
//                      counts as missed
//   grazing            a sample's ray meets its triangle at |cos| < 0.1
//   texel_boundary     a nearest-filtered texture lookup lies within
//                      kTexelEdgeRoundings float roundings of the uv from a
//                      texel edge (texture/texel_edge.h)
//   triangle_edge      a sample's hit lies within kTriangleEdgePixels of an
//                      edge of its triangle, in the image plane
//                      (camera/triangle_edge.h): another renderer may give
//                      the sample to the neighbouring triangle or let it
//                      through a crack between the two
//   unexplained        none of these
// Each test reads the diagnostics of either image (the reference's, or a
// copy of them given to another renderer's image); an image without them
// explains nothing.
#pragma once

#include <array>
#include <string>

#include "image/image.h"

namespace xval {

enum class PixelClass { BackfacingNormal, OcclusionEdge, Grazing, TexelBoundary, TriangleEdge, Unexplained };
inline constexpr int kPixelClassCount = 6;

struct PixelClassInfo {
  PixelClass id;
  const char* key;          // in results.json
  const char* name;         // for people
  const char* explanation;  // one line
  const char* doc_anchor;   // the section of docs/pixel-classes.md
};

// In the order of the classification above.
extern const std::array<PixelClassInfo, kPixelClassCount> kPixelClasses;
inline const PixelClassInfo& pixelClassInfo(PixelClass c) { return kPixelClasses[size_t(c)]; }

// The doc the anchors are in, relative to the repository root.
inline constexpr const char* kPixelClassDoc = "docs/pixel-classes.md";

// Grazing: float rounding of a hit point moves it by ~1/|cos|; below 0.1
// that is more than ten-fold.
inline constexpr float kGrazingCos = 0.1f;
// A depth jump: more than 5% of the pixel's depth to a neighbour's.
inline constexpr float kDepthJump = 0.05f;
// Texel boundary: within this many float32 roundings of the uv
// (texture/texel_edge.h). Measured on the reference set
// (docs/pixel-classes.md, "Texel boundary").
inline constexpr float kTexelEdgeRoundings = 64.0f;
// Triangle edge: within 2^-8 pixel of an edge in the image plane, the
// sub-pixel grid a rasteriser snaps vertices to (the largest of the
// renderers' roundings of an edge; derived in camera/triangle_edge.h).
inline constexpr float kTriangleEdgePixels = 1.0f / 256.0f;

// The class of pixel (x, y), both images covering it; a and b the same
// size.
PixelClass classifyPixel(const Image& a, const Image& b, int x, int y);

}  // namespace xval
