// How close a nearest-filtered texture lookup is to picking another texel,
// measured in units of the float rounding of its texture coordinate.
//
// Nearest filtering picks texel floor(frac(u) W) (texture/texture.h): the
// pick changes at the texel edges u = k / W (k integer; wrap: every whole
// u). A renderer that interpolates the uv in float32 (POV-Ray, Blender)
// rounds each product and sum of b0 u0 + b1 u1 + b2 u2 by at most half an
// ulp of the largest |u_k|, so a uv within a few such roundings of an edge
// may fall on the other side in that renderer, and take the neighbouring
// texel's colour (docs/pixel-classes.md, "Texel boundary").
//
// Per axis: d = |frac(u) W - round(frac(u) W)| / W (uv units), s = 2^-24
// max_k |u_k| (one float32 rounding of the triangle's uvs); the result is
// min over the axes of d / s. An axis whose uvs are all 0 is never near in
// this sense (kFarFromTexelEdge).
#pragma once

#include <glm/glm.hpp>

#include "image/channel_sentinels.h"

#include <algorithm>
#include <cmath>

namespace xval {

// uv: the hit's uv (any whole offset: only frac counts); corners: the
// triangle's three uvs; w, h: the texture's size in texels.
template <class T>
double texelEdgeRoundings(glm::vec<2, T> uv, const glm::vec<2, T> corners[3], int w, int h) {
  double result = kFarFromTexelEdge;
  const int size[2] = {w, h};
  for (int axis = 0; axis < 2; ++axis) {
    const double u = double(uv[axis]);
    const double s = std::ldexp(std::max({std::abs(double(corners[0][axis])), std::abs(double(corners[1][axis])),
                                          std::abs(double(corners[2][axis]))}),
                                -24);
    if (!(s > 0.0) || !std::isfinite(u)) continue;
    const double texels = (u - std::floor(u)) * size[axis];
    const double d = std::abs(texels - std::round(texels)) / size[axis];
    result = std::min(result, d / s);
  }
  return result;
}

}  // namespace xval
