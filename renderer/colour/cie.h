// CIE XYZ and the CIE lightness L*, for the luma-only mode's CIE L* space
// (colour/luma_only.h, docs/models.md "Luma-only lighting").
//
// The renderer's RGB is taken as linear light in the sRGB / Rec. 709
// primaries (its light arithmetic is linear: colours add and multiply), so
// XYZ = kRgbToXyz rgb with the matrix of IEC 61966-2-1 (sRGB), 4 decimals
// as the standard prints them. Its inverse is computed from it (the
// standard's printed inverse is rounded separately and is not its exact
// inverse). The white point is the matrix's image of RGB white (1,1,1):
// (0.9505, 1.0000, 1.0890), D65 as the sRGB matrix rounds it, so a grey
// has a* = b* = 0 (and u* = v* = 0) and white has L* = 100.
//
// L* = 116 f(Y / Yn) - 16, with CIE 15's
//   f(t) = t^(1/3)                       t > (6/29)^3
//        = t / (3 (6/29)^2) + 4/29       otherwise (also t < 0),
// the same L* in CIELAB and CIELUV. Its inverse f^-1(u) = u^3 for
// u > 6/29, else 3 (6/29)^2 (u - 4/29).
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace xval::colour {

inline constexpr double kRgbToXyz[3][3] = {
    {0.4124, 0.3576, 0.1805},
    {0.2126, 0.7152, 0.0722},
    {0.0193, 0.1192, 0.9505}};

namespace cie_detail {
constexpr double det3(const double (&m)[3][3]) {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}
struct Mat3 {
  double m[3][3];
};
// The inverse by cofactors, in double.
constexpr Mat3 inverse3(const double (&a)[3][3]) {
  const double d = det3(a);
  Mat3 r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      r.m[i][j] = (a[i1][j1] * a[i2][j2] - a[i1][j2] * a[i2][j1]) / d;
    }
  return r;
}
}  // namespace cie_detail

inline constexpr cie_detail::Mat3 kXyzToRgb = cie_detail::inverse3(kRgbToXyz);
// The white point: kRgbToXyz (1,1,1).
inline constexpr double kWhiteXyz[3] = {kRgbToXyz[0][0] + kRgbToXyz[0][1] + kRgbToXyz[0][2],
                                        kRgbToXyz[1][0] + kRgbToXyz[1][1] + kRgbToXyz[1][2],
                                        kRgbToXyz[2][0] + kRgbToXyz[2][1] + kRgbToXyz[2][2]};
// f's knee (6/29)^3 and 6/29, and the linear segment's slope 1 / (3 (6/29)^2).
inline constexpr double kLabDelta = 6.0 / 29.0;
inline constexpr double kLabKnee = kLabDelta * kLabDelta * kLabDelta;
inline constexpr double kLabSlope = 1.0 / (3.0 * kLabDelta * kLabDelta);

// (X/Xn, Y/Yn, Z/Zn) of a linear RGB colour, each row summed left to right.
template <class T> glm::vec<3, T> relativeXyz(glm::vec<3, T> c) {
  glm::vec<3, T> o;
  for (int r = 0; r < 3; ++r)
    o[r] = (T(kRgbToXyz[r][0] / kWhiteXyz[r]) * c.x + T(kRgbToXyz[r][1] / kWhiteXyz[r]) * c.y) +
           T(kRgbToXyz[r][2] / kWhiteXyz[r]) * c.z;
  return o;
}
// The linear RGB colour of relative XYZ t (the inverse of relativeXyz).
template <class T> glm::vec<3, T> rgbOfRelativeXyz(glm::vec<3, T> t) {
  glm::vec<3, T> o;
  for (int r = 0; r < 3; ++r)
    o[r] = (T(kXyzToRgb.m[r][0] * kWhiteXyz[0]) * t.x + T(kXyzToRgb.m[r][1] * kWhiteXyz[1]) * t.y) +
           T(kXyzToRgb.m[r][2] * kWhiteXyz[2]) * t.z;
  return o;
}
// Y / Yn of a linear RGB colour: the relative luminance, 1 for white.
template <class T> T relativeLuminance(glm::vec<3, T> c) { return relativeXyz(c).y; }

// CIE 15's f and its inverse (above).
template <class T> T labF(T t) {
  return t > T(kLabKnee) ? std::cbrt(t) : t * T(kLabSlope) + T(4.0 / 29.0);
}
template <class T> T labFInverse(T u) {
  return u > T(kLabDelta) ? u * u * u : (u - T(4.0 / 29.0)) / T(kLabSlope);
}
// L* = 116 f(Y/Yn) - 16.
template <class T> T lightness(T relative_y) { return T(116) * labF(relative_y) - T(16); }

}  // namespace xval::colour
