// Supersampling in the external renderers: an n x n stratified grid per
// pixel (render.spp = n^2) rendered as one sample through each pixel centre
// of an image n times as wide and n times as high, then box-filtered.
//
// Why that is the reference renderer's grid: the reference samples pixel
// (i, j) at image coordinates (i + (sx + 0.5)/n, j + (sy + 0.5)/n),
// sx, sy in [0, n) (render/renderer.h). Scaled by n, that is
// (n i + sx + 0.5, n j + sy + 0.5): the centre of pixel (n i + sx, n j + sy)
// of the n W x n H image. The camera (position, direction, field of view,
// aspect W/H) is unchanged, so only the resolution differs.
//
// The box filter (boxFilter) is the reference renderer's: every sample's
// colour is saturated first, then the n x n samples of a pixel are averaged
// with background samples counted as 0, so colour is premultiplied by
// coverage and alpha is the fraction of samples that hit.
#pragma once

#include "image/image.h"
#include "scene/scene.h"

namespace xval {

// The image an external renderer makes for a scene: n sub-pixels per side
// and its size, n W x n H.
struct SubpixelGrid {
  int n = 1;
  int width = 0, height = 0;
};

// The grid of scene.render.spp. Throws ExportError naming render.spp and
// its value when spp is not a perfect square in [1, kMaxSpp] (the scene
// format's limit), or when the n W x n H image would exceed what an image
// read back may be (kMaxImageSide a side, kMaxImagePixels in all:
// image/image.h) or the default memory budget (scene_file/scene_budget.h,
// kBytesPerPixel per pixel of that image): checked before anything is
// exported or allocated.
SubpixelGrid subpixelGrid(const Scene& scene);

// The W x H image of an (n W) x (n H) image of one sample per pixel:
//   out.rgba[c](i, j) = 1/n^2 sum_{sx, sy < n} saturate(fine.rgba[c](n i + sx, n j + sy)),  c = R, G, B
//   out.alpha(i, j)   = 1/n^2 sum_{sx, sy < n} fine.alpha(n i + sx, n j + sy)
//   out.raw[c](i, j)  = 1/n^2 sum_{sx, sy < n} fine.raw[c](n i + sx, n j + sy)  (only when fine has raw)
// Sums in double. A sample with alpha 0 must have colour 0 (the caller's
// background). Throws std::invalid_argument unless n >= 1 and fine's sides
// are multiples of n. n = 1 saturates the colour and changes nothing else.
Image boxFilter(const Image& fine, int n);

}  // namespace xval
