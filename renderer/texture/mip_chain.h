// MipChain: the mip-maps of a texture and the trilinear lookup of the
// paper's listing's sampler (MIN_MAG_MIP_LINEAR), as the reference defines
// them, so that a GPU's choice can be compared with it.
//
// Chain. Level 0 is the texture (W_0 x H_0 = W x H). Level k+1 is
//   W_{k+1} = max(1, floor(W_k / 2)),  H_{k+1} = max(1, floor(H_k / 2)),
// and its texel (i, j) is the bilinear interpolation of level k (clamped,
// between texel centres, texel n's centre at n) at
//   x = (i + 1/2) W_k / W_{k+1} - 1/2,  y = (j + 1/2) H_k / H_{k+1} - 1/2:
// the centre of texel (i, j) when level k+1 is stretched over the whole of
// level k. With x0 = floor(x), fx = x - x0, x1 = min(x0 + 1, W_k - 1) (the
// same in y),
//   t_{k+1}(i, j) = (1-fx)(1-fy) t_k(x0, y0) + fx (1-fy) t_k(x1, y0)
//                 + (1-fx) fy t_k(x0, y1) + fx fy t_k(x1, y1).
// Where W_k is even, x = 2i + 1/2: the mean of columns 2i and 2i+1, the
// 2x2 box filter. Where W_k = 2m + 1 is odd, the step W_k / W_{k+1} is
// 2 + 1/m, so every column of level k counts (none is left out) and the
// taps drift across the 2x2 blocks; x stays within [1/2, W_k - 3/2], so
// no lookup reaches past an edge and the wrap mode plays no part. Where
// W_k = 1, x = 0: the one column (its weight split in halves between two
// taps on it, so that a power-of-two chain is bit-identical to the 2x2
// box). Weights exact (x is a ratio of integers), sums in double, each
// level rounded to float once. The chain ends at 1 x 1: q + 1 levels,
// q = floor(log2(max(W, H))).
//
// Why this rule: it is what the drivers build. glGenerateTextureMipmap on
// Mesa (gl's uploadTexture; EEVEE's image textures, which Blender mip-maps
// with the same call) blits each level from the whole previous one with a
// linear filter: texel centre (i + 1/2) / W_{k+1} in normalised
// coordinates of level k (docs/scene-format.md, "Trilinear filtering",
// cites the sources). The OpenGL specification leaves the filter to the
// implementation; other drivers may differ for odd sizes.
//
// Level. For the uv derivatives along the image's x and y at the sample
// (per step of the sample grid: one pixel at 1 spp, 1/n of a pixel at
// n x n spp), in texels of level 0,
//   rho    = max(sqrt((W du/dx)^2 + (H dv/dx)^2), sqrt((W du/dy)^2 + (H dv/dy)^2))
//   lambda = log2(rho), clamped to [0, q]  (OpenGL 4.5's scale factor and
//            level of detail, with no bias and no anisotropy);
// lambda <= 0 is magnification, the bilinear lookup of level 0 (the
// listing's MAG_LINEAR), which is what the blend below gives there.
// Blend (LINEAR_MIPMAP_LINEAR): d = floor(lambda), f = lambda - d,
//   C = (1 - f) bilinear_d(uv) + f bilinear_{min(d + 1, q)}(uv),
// each bilinear lookup texture.h's on its level's own W_k x H_k, wrapping.
// A non-finite rho (a sample seeing the triangle edge-on) takes level q.
//
// The derivatives come from the ray differentials of the camera ray
// (render/renderer.cpp, uvFootprint): exact derivatives at the sample, not
// a GPU's finite differences over a 2x2 quad of pixels, so where lambda is
// near a whole number a GPU may blend other levels or weights.
#pragma once

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "texture/texture.h"

namespace xval {

struct MipChain {
  std::vector<Texture> levels;  // levels[0] is the texture itself

  int maxLevel() const { return int(levels.size()) - 1; }  // q

  // The level of detail lambda for uv derivatives (see above).
  double lambda(glm::dvec2 duv_dx, glm::dvec2 duv_dy) const {
    const double w = levels[0].width, h = levels[0].height;
    const double rho = std::max(std::hypot(w * duv_dx.x, h * duv_dx.y), std::hypot(w * duv_dy.x, h * duv_dy.y));
    if (!std::isfinite(rho)) return maxLevel();
    return rho > 1.0 ? std::min(std::log2(rho), double(maxLevel())) : 0.0;
  }

  template <class T>
  glm::vec<3, T> lookup(glm::vec<2, T> uv, double lambda) const {
    const int d = std::min(int(std::floor(lambda)), maxLevel());
    const T f = T(lambda - d);
    const glm::vec<3, T> c0 = levels[size_t(d)].lookup(uv, TextureFilter::Bilinear);
    if (f == T(0)) return c0;
    const glm::vec<3, T> c1 = levels[size_t(std::min(d + 1, maxLevel()))].lookup(uv, TextureFilter::Bilinear);
    return c0 * (T(1) - f) + c1 * f;
  }
};

// The chain of t (see above).
MipChain mipChain(const Texture& t);

}  // namespace xval
