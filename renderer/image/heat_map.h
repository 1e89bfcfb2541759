// Heat maps of a difference image, as the report and the extremes matrix
// show them.
//
// Per pixel: the largest channel difference e (in 1/65535) mapped to
// black -> blue -> cyan -> green -> yellow -> red -> white; e in [0, 1]
// linearly over the first seventh of the scale, then logarithmically up to
// kHeatMax16 = 4096 at white; NaN at the top. Pixels neither render covers
// (alpha 0) are grey 0.35.
#pragma once

#include <filesystem>
#include <string>

#include "image/image.h"

namespace xval {

inline constexpr double kHeatMin16 = 1.0, kHeatMax16 = 4096.0;

// The scale's colour at t in [0, 1] (clamped; NaN gives t = 0): seven
// knots (the colours above) equally spaced, linear in float between them.
// rgb receives 3 floats.
void heatRampColour(float t, float* rgb);

// diff: a difference image (image/compare.h differenceImage): |a - b| per
// channel, alpha = covered by either. Returns the RGB heat map, alpha 1.
Image heatMap(const Image& diff);

// A difference image made at most max_side pixels a side by the smallest
// integer factor k that does it: each output pixel holds, per channel, the
// largest value of its k x k block (alpha: covered when any is), so a
// single bad pixel survives the preview (a box filter would divide it by
// k^2). k = 1 returns the image as it is.
Image maxDownscaled(const Image& diff, int max_side);

// The colour scale itself, 512 x 16, left = 0, right = kHeatMax16.
void writeHeatScalePng(const std::filesystem::path& png);

// The heat map of one pair (heatMap above) at full resolution up to
// max_side px a side (larger: reduced by the block maximum, so a single bad
// pixel stays visible)
// as results_dir/rel (validate names it: validate/compare_outputs.h);
// returns rel, for the pair's `heat_map` in results.json.
inline constexpr int kHeatMapSide = 1024;
// A pair's precision bound map (`bound_map`): smaller, since it is looked
// at beside the heat map, not searched pixel by pixel (the block maximum
// keeps each block's largest bound).
inline constexpr int kBoundMapSide = 128;
std::string writeHeatMapPng(const Image& diff, const std::filesystem::path& results_dir, const std::string& rel,
                            int max_side = kHeatMapSide);

}  // namespace xval
