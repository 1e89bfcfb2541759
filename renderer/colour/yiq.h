// YIQ, the colour space of the paper's luma model (paper eq. 4-5 and the
// Table 1 listing), below both the lighting models (shading/models.h) and
// the image metrics (image/perceptual.h), which read the same matrices.
//
// The listing's coefficients, verbatim (8 decimals). The rows of kRgbToYiq
// give Y, I, Q from R, G, B as the model reads them (display-referred
// codes, no transfer function); kYiqToRgb is the listing's inverse, whose
// first column is exactly (1, 1, 1). The luma row sums to 1.00000001, not
// 1 (shading/models.h lightLuma normalises it for light colours).
#pragma once

#include <glm/glm.hpp>

namespace xval::colour {

inline constexpr double kRgbToYiq[3][3] = {
    {0.29889531, 0.58662247, 0.11448223},
    {0.59597799, -0.27417610, -0.32180189},
    {0.21147017, -0.52261711, 0.31114694}};
inline constexpr double kYiqToRgb[3][3] = {
    {1.0, 0.95608445, 0.62088850},
    {1.0, -0.27137664, -0.64860590},
    {1.0, -1.10561724, 1.70250126}};

// Y = the first row . c, in the scalar T of c.
template <class T> T luma(glm::vec<3, T> c) {
  return T(kRgbToYiq[0][0]) * c.x + T(kRgbToYiq[0][1]) * c.y + T(kRgbToYiq[0][2]) * c.z;
}
// (Y, I, Q) = kRgbToYiq c, each row summed left to right in T.
template <class T> glm::vec<3, T> rgbToYiq(glm::vec<3, T> c) {
  glm::vec<3, T> o;
  for (int r = 0; r < 3; ++r)
    o[r] = T(kRgbToYiq[r][0]) * c.x + T(kRgbToYiq[r][1]) * c.y + T(kRgbToYiq[r][2]) * c.z;
  return o;
}
// (R, G, B) = kYiqToRgb yiq, unsaturated (the listing saturates; callers
// that need it do so once).
template <class T> glm::vec<3, T> yiqToRgb(glm::vec<3, T> yiq) {
  glm::vec<3, T> o;
  for (int r = 0; r < 3; ++r)
    o[r] = T(kYiqToRgb[r][0]) * yiq.x + T(kYiqToRgb[r][1]) * yiq.y + T(kYiqToRgb[r][2]) * yiq.z;
  return o;
}

}  // namespace xval::colour
