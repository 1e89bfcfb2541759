// Why two renders of one scene may differ at a pixel, and by how much at
// most: each known cause with the largest difference it can produce at
// that pixel, computed by the reference renderer from the scene
// (docs/pixel-classes.md). A cause explains a pixel only up to its bound;
// a pixel no cause explains is "unexplained", capped by the tolerance's
// max_unexplained_16bit (image/compare.h).
//
// The bounds at a pixel p (fractions of full scale), from the reference's
// diagnostics channels (image/image.h) and the two renderers' precision
// models (image/precision_bound.h):
//   E(p)  edge: edge_fraction, the share of p's samples whose first hit the
//         renderers' rounding may change (a sample within 2^-8 px of a
//         triangle's boundary). Each such sample weighs 1/n^2 in the box
//         filter and its saturated colour lies in [0, 1], so it moves the
//         pixel's coverage and each premultiplied channel by at most
//         1/n^2: together by at most E(p).
//   F(p)  backfacing normal: backfacing_flip, what turning the normal of
//         p's backfacing samples around changes (POV-Ray turns them, the
//         paper's shader does not); 0 where no sample is backfacing.
//   P(p)  precision: B_a(p) + B_b(p), what the two renderers' rounding of
//         hit point, uv, normal and arithmetic can move the value.
// With tol the tolerance's max_abs, a covered pixel with error e and
// coverage difference da (|alpha_a - alpha_b|) is
//   within       e <= tol (and da <= tol + E)
//   precision    e <= tol + P (and da <= tol + E)
//   edge         e <= tol + P + E + F, da <= tol + E, and E >= F
//   backfacing   e <= tol + P + E + F, da <= tol + E, and F > E
//   unexplained  otherwise.
// A pixel only one image covers (a mask disagreement) is explained when
// its whole coverage difference is edge samples: da <= E (its colour
// difference is then at most E as well).
// An image pair without the diagnostics explains nothing.
#pragma once

#include <array>
#include <string>

#include "image/image.h"

namespace xval {

enum class PixelClass { Precision, Edge, BackfacingNormal, Unexplained };
inline constexpr int kPixelClassCount = 4;

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

// Triangle edge: within 2^-8 pixel of an edge in the image plane, the
// sub-pixel grid a rasteriser snaps vertices to (the largest of the
// renderers' roundings of an edge; derived in camera/triangle_edge.h).
inline constexpr float kTriangleEdgePixels = 1.0f / 256.0f;

// The texel_edge channel's scale (texture/texel_edge.h): golden images
// keep its values on either side of it (golden/golden_set.h). No class
// reads it since the precision bound took over (the uv probe sees a
// nearest texel's edge itself).
inline constexpr float kTexelEdgeRoundings = 64.0f;

// The bounds at one pixel (fractions of full scale).
struct PixelBounds {
  double edge = 0.0;        // E
  double backfacing = 0.0;  // F
  double precision = 0.0;   // P
};

// The class of a covered pixel with error e and coverage difference da,
// under tolerance tol and bounds b (the rule above).
PixelClass classifyPixel(double e, double da, double tol, const PixelBounds& b);

// Whether a pixel only one image covers is explained: da <= E.
bool maskDisagreementExplained(double da, const PixelBounds& b);

struct PrecisionModel;
// The bounds at pixel (x, y) from `diagnostics` (the image carrying the
// reference's channels; none: all 0) and the pair's precision models;
// value: the pixel's largest colour channel, of either image.
PixelBounds pixelBounds(const Image& diagnostics, int x, int y, double value, const PrecisionModel& a,
                        const PrecisionModel& b);

// The image of the two whose diagnostics the bounds read: a's when it has
// the edge channel, else b's, else null.
const Image* boundsDiagnostics(const Image& a, const Image& b);

}  // namespace xval
