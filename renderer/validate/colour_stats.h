// Colour statistics of a render, for checking the paper's qualitative
// claims with numbers (docs/paper-claims.md).
//
// Over the pixels that hit and are lit (luma of the final colour > 0.02),
// with colours taken as sRGB-encoded and converted to CIELAB (perceptual.h):
//   mean_chroma:        mean C* of the render;
//   mean_albedo_chroma: mean C* of the surface colour (texture) there;
//   grey_fraction:      share of those pixels with C* < 5 (no visible hue);
//   hue_error_deg:      mean |h(render) - h(surface)| (circular, degrees)
//                       over the pixels where both have C* >= 5;
//   lit_pixels:         how many pixels the statistics cover.
#pragma once

#include "image/image.h"

namespace xval {

struct ColourStats {
  long long lit_pixels = 0;
  double mean_chroma = 0, mean_albedo_chroma = 0, grey_fraction = 0, hue_error_deg = 0;
};

// Needs the reference renderer's albedo channels; throws otherwise.
ColourStats colourStats(const Image& reference_render);

}  // namespace xval
