// The value a diagnostics channel (image/image.h, Image::texel_edge and
// Image::triangle_edge) holds where its distance does not apply: no sample
// hit, no nearest-filtered texture, a degenerate triangle. Far above any
// real distance, so "min over the samples" keeps a real one, and finite, so
// the EXR stores it exactly.
#pragma once

namespace xval {

// "Not near a texel edge" (texture/texel_edge.h).
inline constexpr float kFarFromTexelEdge = 3.0e38f;
// "Not near a triangle edge" (camera/triangle_edge.h).
inline constexpr float kFarFromTriangleEdge = 3.0e38f;

}  // namespace xval
