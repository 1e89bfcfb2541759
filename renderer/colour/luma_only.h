// The luma-only mode (docs/models.md "Luma-only lighting"): the paper's
// construction, light applied to the luma and the chroma untouched, for
// any lighting model of the registry (shading/model/registry.h), with the
// luma space a parameter (the material's "luma_only"):
//
//   1. the model is evaluated as it is, on grey inputs: the surface colour
//      C replaced by Y_C (1,1,1) and every light colour Lc (ambient
//      included) by Y(Lc) (1,1,1), giving the lit grey G (a colour when
//      the model has coloured parameters such as c0);
//   2. Y_out = Y(G), the lit luma;
//   3. the result has C's chroma and the luma Y_out:
//        yiq:       F = C + (Y_out - Y_C) (1,1,1)
//                   (I and Q of C kept: the first column of the listing's
//                   YIQ->RGB is exactly (1,1,1));
//        cie_lstar: F = the colour of lightness L*(Y_out) and C's a*, b*:
//                   in relative XYZ t = (X/Xn, Y/Yn, Z/Zn) of C,
//                   F = rgb(f^-1(f(t) + (f(Y_out) - f(Y_C)) (1,1,1)))
//                   (a* = 500 (f(tx) - f(ty)) and b* = 200 (f(ty) - f(tz))
//                   are unchanged when all three f move by the same amount;
//                   colour/cie.h).
//
// The lumas, each normalised so that white is exactly 1:
//   yiq:       Y(Lc) and Y(G) the listing's luma row normalised
//              (models::lightLuma); Y_C the listing's row as it is
//              (models::luma, as the yiq_luma model reads C);
//   cie_lstar: the relative luminance Y/Yn (sRGB primaries, white point
//              the sRGB matrix's D65) for all three.
// Nothing is clamped here: the renderer saturates the final colour once
// per sample, as every model's (out-of-gamut CIE results are clipped per
// channel there).
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <string_view>
#include <vector>

#include "colour/cie.h"
#include "colour/yiq.h"

namespace xval {

enum class LumaSpace { Yiq, CieLstar };
// The scene-file names, by LumaSpace.
inline constexpr std::array<std::string_view, 2> kLumaSpaceNames = {"yiq", "cie_lstar"};
inline const char* toString(LumaSpace s) { return kLumaSpaceNames[size_t(s)].data(); }

namespace luma_only {

template <class T> using vec3 = glm::vec<3, T>;

// Y of a light colour or of the lit grey G, white = 1.
template <class T> T lightLuma(LumaSpace s, vec3<T> c) {
  if (s == LumaSpace::CieLstar) return colour::relativeLuminance(c);
  constexpr double white = colour::kRgbToYiq[0][0] + colour::kRgbToYiq[0][1] + colour::kRgbToYiq[0][2];
  return T(colour::kRgbToYiq[0][0] / white) * c.x + T(colour::kRgbToYiq[0][1] / white) * c.y +
         T(colour::kRgbToYiq[0][2] / white) * c.z;
}
// Y_C, the surface colour's luma.
template <class T> T surfaceLuma(LumaSpace s, vec3<T> c) {
  return s == LumaSpace::CieLstar ? colour::relativeLuminance(c) : colour::luma(c);
}
// Step 3: C with its luma Y_c replaced by y_out, its chroma kept.
template <class T> vec3<T> withLuma(LumaSpace s, vec3<T> c, T y_c, T y_out) {
  if (s == LumaSpace::Yiq) return c + vec3<T>(y_out - y_c);
  const vec3<T> t = colour::relativeXyz(c);
  const T d = colour::labF(y_out) - colour::labF(y_c);
  return colour::rgbOfRelativeXyz(vec3<T>(colour::labFInverse(colour::labF(t.x) + d), colour::labFInverse(colour::labF(t.y) + d),
                                          colour::labFInverse(colour::labF(t.z) + d)));
}

}  // namespace luma_only
}  // namespace xval
