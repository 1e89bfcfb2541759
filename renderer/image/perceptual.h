// Perceptual colour differences and structural similarity.
//
// Inputs are colours in the models' stored encoding. For CIELAB they are
// taken as sRGB-encoded (IEC 61966-2-1; display-referred 8-bit texture
// values are), decoded to linear sRGB, then XYZ (D65) and CIELAB with the
// D65 reference white (the last step by lcms2's cmsXYZ2Lab).
//   ciede2000: Sharma, Wu, Dalal, "The CIEDE2000 color-difference
//              formula: implementation notes ..." (2005), kL = kC = kH = 1,
//              computed by lcms2 (cmsCIE2000DeltaE);
//   yiqDelta:  Kotsarenko & Ramos (2010), "Measuring perceived color
//              difference using YIQ NTSC transmission color space in mobile
//              applications": sqrt(0.5053 dY^2 + 0.299 dI^2 + 0.1957 dQ^2)
//              with the YIQ matrix of their 2012 listing (models.h);
//   ssim:      Wang, Bovik, Sheikh, Simoncelli (2004) on the YIQ luma, an
//              11x11 Gaussian window (sigma 1.5), K1 = 0.01, K2 = 0.03,
//              dynamic range 1, averaged over the windows centred on
//              pixels both images cover.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace xval {

// The steps of srgbToLab, each written once (image/flip.h reuses them):
// the sRGB decoding of one code value (IEC 61966-2-1), linear sRGB ->
// XYZ (D65) and its inverse, and XYZ -> CIELAB with the D65 white.
double srgbDecode(double code);
glm::dvec3 linearSrgbToXyz(glm::dvec3 linear);
glm::dvec3 xyzToLinearSrgb(glm::dvec3 xyz);
glm::dvec3 xyzToLab(glm::dvec3 xyz);
inline constexpr double kD65White[3] = {0.95047, 1.0, 1.08883};  // XYZ of the reference white
glm::dvec3 srgbToLab(glm::dvec3 srgb);
double ciede2000(glm::dvec3 lab1, glm::dvec3 lab2);
double yiqDelta(glm::dvec3 rgb1, glm::dvec3 rgb2);

struct PerceptualMetrics {
  double ssim = 1.0;
  double ciede2000_mean = 0.0, ciede2000_max = 0.0;
  double yiq_mean = 0.0, yiq_max = 0.0;
};

// What perceptualMetrics reads of one image, computed once for every pair
// the image is in (a case of n renders has n - 1 pairs per render): each
// pixel's luma (models::luma) and, where the image covers the pixel
// (alpha > 0), its srgbToLab; (0, 0, 0) elsewhere. The metrics from it are
// bit for bit those computed from the images alone (the same operations
// on the same values).
struct PerceptualImage {
  int width = 0, height = 0;
  std::vector<double> luma;
  std::vector<glm::dvec3> lab;
};
PerceptualImage perceptualImage(const Image& img);

// Over the pixels both images cover (alpha > 0).
PerceptualMetrics perceptualMetrics(const Image& a, const Image& b);
// The same from each image's perceptualImage (pa of a, pb of b).
PerceptualMetrics perceptualMetrics(const Image& a, const PerceptualImage& pa, const Image& b,
                                    const PerceptualImage& pb);

}  // namespace xval
