#include "image/perceptual.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <lcms2.h>

#include "colour/yiq.h"

namespace xval {

double srgbDecode(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

namespace {
// Linear sRGB -> XYZ (D65), IEC 61966-2-1 (glm is column-major: each
// glm::dvec3 below is a column, the XYZ of one primary).
const glm::dmat3 kLinearSrgbToXyz(glm::dvec3(0.4124564, 0.2126729, 0.0193339),
                                  glm::dvec3(0.3575761, 0.7151522, 0.1191920),
                                  glm::dvec3(0.1804375, 0.0721750, 0.9503041));
const glm::dmat3 kXyzToLinearSrgb = glm::inverse(kLinearSrgbToXyz);
}  // namespace

glm::dvec3 linearSrgbToXyz(glm::dvec3 l) { return kLinearSrgbToXyz * l; }
glm::dvec3 xyzToLinearSrgb(glm::dvec3 xyz) { return kXyzToLinearSrgb * xyz; }

// The decoding and the matrix are written here, the CIELAB step is lcms2's:
// its profile route (cmsCreate_sRGBProfile -> cmsCreateLab4Profile with
// the D65 white, relative colorimetric) goes through the ICC's D50
// connection space and gave L*a*b* up to 11.6 away from this D65
// definition on 1e5 random colours; cmsXYZ2Lab with the D65 white below
// agrees with the textbook formula to 2.9e-13 (1e6 random colours).
glm::dvec3 xyzToLab(glm::dvec3 x) {
  static const cmsCIEXYZ kWhite{kD65White[0], kD65White[1], kD65White[2]};
  const cmsCIEXYZ xyz{x.x, x.y, x.z};
  cmsCIELab lab;
  cmsXYZ2Lab(&kWhite, &lab, &xyz);
  return {lab.L, lab.a, lab.b};
}

glm::dvec3 srgbToLab(glm::dvec3 c) {
  return xyzToLab(linearSrgbToXyz(glm::dvec3(srgbDecode(c.r), srgbDecode(c.g), srgbDecode(c.b))));
}

// lcms2's CIEDE2000 agrees with Sharma et al.'s formula as written out to
// 8e-15 on their 34 test pairs and to 1.3e-13 on 1e6 random sRGB pairs.
double ciede2000(glm::dvec3 lab1, glm::dvec3 lab2) {
  const cmsCIELab a{lab1.x, lab1.y, lab1.z}, b{lab2.x, lab2.y, lab2.z};
  return cmsCIE2000DeltaE(&a, &b, 1.0, 1.0, 1.0);
}

double yiqDelta(glm::dvec3 a, glm::dvec3 b) {
  glm::dvec3 d = colour::rgbToYiq(a) - colour::rgbToYiq(b);
  return std::sqrt(0.5053 * d.x * d.x + 0.299 * d.y * d.y + 0.1957 * d.z * d.z);
}

PerceptualImage perceptualImage(const Image& img) {
  PerceptualImage p;
  p.width = img.width, p.height = img.height;
  const size_t n = size_t(img.width) * img.height;
  p.luma.resize(n);
  p.lab.assign(n, glm::dvec3(0.0));
  for (size_t i = 0; i < n; ++i) {
    const float* px = &img.rgba[i * 4];
    const glm::dvec3 c(px[0], px[1], px[2]);
    p.luma[i] = colour::luma(c);
    if (px[3] > 0) p.lab[i] = srgbToLab(c);
  }
  return p;
}

PerceptualMetrics perceptualMetrics(const Image& a, const Image& b) {
  return perceptualMetrics(a, perceptualImage(a), b, perceptualImage(b));
}

namespace {
// SSIM's window: an 11x11 Gaussian (sigma 1.5), the weight of tap
// (dx, dy) the product w[dx + 5] * w[dy + 5], clipped at the border and
// normalised by the sum of the weights inside the image.
struct SsimWindow {
  double w[11];
  double k[121];       // w[dx + 5] * w[dy + 5], row by row (dy outer)
  double sum_full;     // the sum of k in that order: a window inside the image
  double k_full[121];  // k / sum_full
  SsimWindow() {
    for (int i = 0; i < 11; ++i) w[i] = std::exp(-((i - 5) * (i - 5)) / (2.0 * 1.5 * 1.5));
    sum_full = 0;
    for (int dy = -5; dy <= 5; ++dy)
      for (int dx = -5; dx <= 5; ++dx) {
        k[(dy + 5) * 11 + dx + 5] = w[dx + 5] * w[dy + 5];
        sum_full += k[(dy + 5) * 11 + dx + 5];
      }
    for (int i = 0; i < 121; ++i) k_full[i] = k[i] / sum_full;
  }
};

// SSIM of the window centred on (x, y). Every sum runs over the taps in
// the same order (dy outer, dx inner), with the same weights, whether the
// window lies inside the image (no bound checks, the precomputed sum and
// normalised weights) or is clipped at its border, so both give the value
// of one formula bit for bit.
double ssimAt(const SsimWindow& sw_, const std::vector<double>& ya, const std::vector<double>& yb, int W, int H,
              int x, int y) {
  const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  double sw = 0, ma = 0, mb = 0, va = 0, vb = 0, cov = 0;
  if (x >= 5 && y >= 5 && x + 5 < W && y + 5 < H) {
    const double* ra = &ya[size_t(y - 5) * W + (x - 5)];
    const double* rb = &yb[size_t(y - 5) * W + (x - 5)];
    for (int dy = 0; dy < 11; ++dy)
      for (int dx = 0; dx < 11; ++dx) {
        const double k = sw_.k[dy * 11 + dx];
        ma += k * ra[size_t(dy) * W + dx], mb += k * rb[size_t(dy) * W + dx];
      }
    sw = sw_.sum_full;
    ma /= sw, mb /= sw;
    for (int dy = 0; dy < 11; ++dy)
      for (int dx = 0; dx < 11; ++dx) {
        const double k = sw_.k_full[dy * 11 + dx];
        const double da = ra[size_t(dy) * W + dx] - ma, db = rb[size_t(dy) * W + dx] - mb;
        va += k * da * da, vb += k * db * db, cov += k * da * db;
      }
  } else {
    for (int dy = -5; dy <= 5; ++dy)
      for (int dx = -5; dx <= 5; ++dx) {
        const int xx = x + dx, yy = y + dy;
        if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
        const double k = sw_.k[(dy + 5) * 11 + dx + 5];
        sw += k, ma += k * ya[size_t(yy) * W + xx], mb += k * yb[size_t(yy) * W + xx];
      }
    ma /= sw, mb /= sw;
    for (int dy = -5; dy <= 5; ++dy)
      for (int dx = -5; dx <= 5; ++dx) {
        const int xx = x + dx, yy = y + dy;
        if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
        const double k = sw_.k[(dy + 5) * 11 + dx + 5] / sw;
        const double da = ya[size_t(yy) * W + xx] - ma, db = yb[size_t(yy) * W + xx] - mb;
        va += k * da * da, vb += k * db * db, cov += k * da * db;
      }
  }
  return ((2 * ma * mb + C1) * (2 * cov + C2)) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
}
}  // namespace

PerceptualMetrics perceptualMetrics(const Image& a, const PerceptualImage& pa, const Image& b,
                                    const PerceptualImage& pb) {
  PerceptualMetrics m;
  const int W = a.width, H = a.height;
  if (pa.width != W || pa.height != H || pb.width != W || pb.height != H || b.width != W || b.height != H)
    throw std::invalid_argument("perceptualMetrics: the images and their perceptual images differ in size");
  auto covered = [&](int x, int y) { return a.pixel(x, y)[3] > 0 && b.pixel(x, y)[3] > 0; };
  auto rgb = [](const Image& img, int x, int y) {
    const float* p = img.pixel(x, y);
    return glm::dvec3(p[0], p[1], p[2]);
  };
  long long n = 0;
  double de_sum = 0, yiq_sum = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (!covered(x, y)) continue;
      const size_t i = size_t(y) * W + x;
      double de = ciede2000(pa.lab[i], pb.lab[i]);
      double dy = yiqDelta(rgb(a, x, y), rgb(b, x, y));
      de_sum += de, yiq_sum += dy, ++n;
      m.ciede2000_max = std::max(m.ciede2000_max, de);
      m.yiq_max = std::max(m.yiq_max, dy);
    }
  if (n == 0) return m;
  m.ciede2000_mean = de_sum / double(n);
  m.yiq_mean = yiq_sum / double(n);
  static const SsimWindow window;
  double ssim_sum = 0;
  long long windows = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (!covered(x, y)) continue;
      ssim_sum += ssimAt(window, pa.luma, pb.luma, W, H, x, y);
      ++windows;
    }
  m.ssim = ssim_sum / double(windows);
  return m;
}

}  // namespace xval
