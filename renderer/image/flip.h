// LDR-FLIP: the per-pixel perceived difference between two images shown
// alternately ("flipped" between), from Andersson, Nilsson, Akenine-Möller,
// Oskarsson, Åström, Fairchild, "FLIP: A Difference Evaluator for
// Alternating Images", Proc. ACM Comput. Graph. Interact. Tech. 3(2), 2020
// (Section 4 of the paper; written here from its text).
//
// Input: colours as sRGB codes in [0, 1] (xval's images hold display-
// referred codes: docs/scene-format.md "output encoding"), premultiplied by
// coverage, i.e. over black, and clamped to [0, 1]. Output: an error in
// [0, 1] per pixel, 0 where the images cannot be told apart.
//
// Colour pipeline, per image:
//   1. sRGB decode -> linear sRGB -> XYZ (D65) -> YyCxCz (the opponent
//      space of Zhang & Wandell's S-CIELAB, linear in XYZ):
//        Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn);
//   2. each channel convolved with its contrast sensitivity function: the
//      paper's Gaussian fits in frequency, a1 exp(-b1 f^2) + a2 exp(-b2 f^2)
//      (f in cycles per degree), in the spatial domain
//        s(r) = a1 sqrt(pi/b1) exp(-pi^2 r^2/b1) + a2 sqrt(pi/b2) exp(-pi^2 r^2/b2)
//      (r in degrees, r^2 = x^2 + y^2), with (a1, b1, a2, b2) =
//        Yy (achromatic) 1, 0.0047, 0, 1e-5
//        Cx (red-green)  1, 0.0053, 0, 1e-5
//        Cz (blue-yellow) 34.1, 0.04, 13.5, 0.025,
//      sampled at pixel centres (1/ppd degrees apart) out to radius
//      ceil(3 sqrt(b_max / (2 pi^2)) ppd) pixels (b_max = 0.04: three
//      standard deviations of the widest Gaussian), normalised to sum 1;
//      pixels outside the image repeat the nearest edge pixel;
//   3. back to linear sRGB, clamped to [0, 1], to CIELAB (D65), and the
//      Hunt adjustment a* <- 0.01 L* a*, b* <- 0.01 L* b* (chroma looks
//      weaker at low luminance).
// Colour error: the HyAB distance |dL*| + sqrt(da*^2 + db*^2) of the two
// adjusted colours, raised to q_c = 0.7, then redistributed onto [0, 1]:
// with c' = c_max^q_c, where c_max is the HyAB distance of Hunt-adjusted
// pure green and pure blue (the largest in the gamut, per the paper),
//   e < p_c c'  ->  e p_t / (p_c c')
//   else        ->  p_t + (e - p_c c') / (c' - p_c c') (1 - p_t),
// p_c = 0.4, p_t = 0.95 (the paper's cut-off and target).
// Feature error, on the achromatic channel Y/Yn in [0, 1] of each
// (unfiltered) image: an edge detector (first derivative of a Gaussian)
// and a point detector (second derivative), sigma = 0.5 w ppd pixels with
// w = 0.082 degrees, radius ceil(3 sigma); each 2-D kernel is the
// derivative along one axis times the Gaussian along the other, normalised
// so that its positive weights sum to 1 and its negative weights to -1
// (the Gaussian factor sums to 1). A detector's response is the length of
// its (x, y) responses; the feature error is
//   (max(|edge_a - edge_b|, |point_a - point_b|) / sqrt(2))^q_f, q_f = 0.5.
// Combined: colour_error ^ (1 - feature_error).
//
// Everything above is symmetric in the two images. FLIP's viewing
// condition is its pixels per degree; the paper's default 67 is a 0.7 m
// wide 3840-pixel monitor seen from 0.7 m.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"

namespace xval {

inline constexpr double kFlipDefaultPixelsPerDegree = 67.0;

// What the error map reads of one image, computed once for every pair the
// image is in (as image/perceptual.h's PerceptualImage): per pixel, the
// Hunt-adjusted L*a*b* of the CSF-filtered colour and the edge and point
// detectors' responses. The map from two of them is bit for bit the map
// from the two images.
struct FlipImage {
  int width = 0, height = 0;
  double pixels_per_degree = kFlipDefaultPixelsPerDegree;
  std::vector<glm::dvec3> hunt_lab;
  std::vector<double> edge, point;
};
FlipImage flipImage(const Image& img, double pixels_per_degree = kFlipDefaultPixelsPerDegree);

// The error map, row by row (width * height values in [0, 1]). Throws
// std::invalid_argument when the sizes (or the FlipImages' viewing
// distances) differ or ppd is not a finite number > 0.
std::vector<float> flipErrorMap(const Image& a, const Image& b, double pixels_per_degree = kFlipDefaultPixelsPerDegree);
std::vector<float> flipErrorMap(const FlipImage& a, const FlipImage& b);

// Summaries of the map over the pixels either image covers (alpha > 0;
// every pixel of an image read without alpha), as the "either covered"
// errors of image/compare.h: the map itself is computed over the whole
// image, since the filters see the neighbours. p99 is the nearest-rank
// 99th percentile (compare.h). No pixel covered: pixels = 0, both 0.
struct FlipMetrics {
  long long pixels = 0;
  double mean = 0.0;
  double p99 = 0.0;
};
FlipMetrics flipMetrics(const Image& a, const Image& b, double pixels_per_degree = kFlipDefaultPixelsPerDegree);
FlipMetrics flipSummary(const std::vector<float>& map, const Image& a, const Image& b);

}  // namespace xval
