#include "image/perceptual.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "shading/models.h"

namespace xval {

namespace {
constexpr double kPi = 3.14159265358979323846;

double srgbDecode(double v) {
  return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}
double labF(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}
double deg(double rad) { return rad * 180.0 / kPi; }
double rad(double deg) { return deg * kPi / 180.0; }
}  // namespace

glm::dvec3 srgbToLab(glm::dvec3 c) {
  glm::dvec3 l(srgbDecode(c.r), srgbDecode(c.g), srgbDecode(c.b));
  // Linear sRGB -> XYZ (D65), IEC 61966-2-1.
  double X = 0.4124564 * l.r + 0.3575761 * l.g + 0.1804375 * l.b;
  double Y = 0.2126729 * l.r + 0.7151522 * l.g + 0.0721750 * l.b;
  double Z = 0.0193339 * l.r + 0.1191920 * l.g + 0.9503041 * l.b;
  const double Xn = 0.95047, Yn = 1.0, Zn = 1.08883;
  double fx = labF(X / Xn), fy = labF(Y / Yn), fz = labF(Z / Zn);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double ciede2000(glm::dvec3 lab1, glm::dvec3 lab2) {
  const double L1 = lab1.x, a1 = lab1.y, b1 = lab1.z, L2 = lab2.x, a2 = lab2.y, b2 = lab2.z;
  const double C1 = std::hypot(a1, b1), C2 = std::hypot(a2, b2);
  const double Cbar = (C1 + C2) / 2.0;
  const double Cbar7 = std::pow(Cbar, 7.0);
  const double G = 0.5 * (1.0 - std::sqrt(Cbar7 / (Cbar7 + std::pow(25.0, 7.0))));
  const double a1p = (1.0 + G) * a1, a2p = (1.0 + G) * a2;
  const double C1p = std::hypot(a1p, b1), C2p = std::hypot(a2p, b2);
  auto hue = [](double b, double ap) {
    if (b == 0.0 && ap == 0.0) return 0.0;
    double h = deg(std::atan2(b, ap));
    return h < 0.0 ? h + 360.0 : h;
  };
  const double h1p = hue(b1, a1p), h2p = hue(b2, a2p);
  const double dLp = L2 - L1, dCp = C2p - C1p;
  double dhp = 0.0;
  if (C1p * C2p != 0.0) {
    dhp = h2p - h1p;
    if (dhp > 180.0) dhp -= 360.0;
    else if (dhp < -180.0) dhp += 360.0;
  }
  const double dHp = 2.0 * std::sqrt(C1p * C2p) * std::sin(rad(dhp) / 2.0);
  const double Lbarp = (L1 + L2) / 2.0, Cbarp = (C1p + C2p) / 2.0;
  double hbarp = h1p + h2p;
  if (C1p * C2p != 0.0) {
    if (std::abs(h1p - h2p) <= 180.0) hbarp = (h1p + h2p) / 2.0;
    else if (h1p + h2p < 360.0) hbarp = (h1p + h2p + 360.0) / 2.0;
    else hbarp = (h1p + h2p - 360.0) / 2.0;
  }
  const double T = 1.0 - 0.17 * std::cos(rad(hbarp - 30.0)) + 0.24 * std::cos(rad(2.0 * hbarp)) +
                   0.32 * std::cos(rad(3.0 * hbarp + 6.0)) - 0.20 * std::cos(rad(4.0 * hbarp - 63.0));
  const double dTheta = 30.0 * std::exp(-std::pow((hbarp - 275.0) / 25.0, 2.0));
  const double Cbarp7 = std::pow(Cbarp, 7.0);
  const double Rc = 2.0 * std::sqrt(Cbarp7 / (Cbarp7 + std::pow(25.0, 7.0)));
  const double Lm = (Lbarp - 50.0) * (Lbarp - 50.0);
  const double Sl = 1.0 + 0.015 * Lm / std::sqrt(20.0 + Lm);
  const double Sc = 1.0 + 0.045 * Cbarp;
  const double Sh = 1.0 + 0.015 * Cbarp * T;
  const double Rt = -std::sin(rad(2.0 * dTheta)) * Rc;
  const double l = dLp / Sl, c = dCp / Sc, h = dHp / Sh;
  return std::sqrt(l * l + c * c + h * h + Rt * c * h);
}

double yiqDelta(glm::dvec3 a, glm::dvec3 b) {
  glm::dvec3 d = models::rgbToYiq(a) - models::rgbToYiq(b);
  return std::sqrt(0.5053 * d.x * d.x + 0.299 * d.y * d.y + 0.1957 * d.z * d.z);
}

PerceptualMetrics perceptualMetrics(const Image& a, const Image& b) {
  PerceptualMetrics m;
  const int W = a.width, H = a.height;
  auto covered = [&](int x, int y) { return a.pixel(x, y)[3] > 0 && b.pixel(x, y)[3] > 0; };
  auto rgb = [](const Image& img, int x, int y) {
    const float* p = img.pixel(x, y);
    return glm::dvec3(p[0], p[1], p[2]);
  };
  std::vector<double> ya(size_t(W) * H), yb(size_t(W) * H);
  long long n = 0;
  double de_sum = 0, yiq_sum = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      glm::dvec3 ca = rgb(a, x, y), cb = rgb(b, x, y);
      ya[size_t(y) * W + x] = models::luma(ca);
      yb[size_t(y) * W + x] = models::luma(cb);
      if (!covered(x, y)) continue;
      double de = ciede2000(srgbToLab(ca), srgbToLab(cb));
      double dy = yiqDelta(ca, cb);
      de_sum += de, yiq_sum += dy, ++n;
      m.ciede2000_max = std::max(m.ciede2000_max, de);
      m.yiq_max = std::max(m.yiq_max, dy);
    }
  if (n == 0) return m;
  m.ciede2000_mean = de_sum / double(n);
  m.yiq_mean = yiq_sum / double(n);
  // SSIM with an 11x11 Gaussian window (sigma 1.5), clipped at the border.
  double w[11];
  for (int i = 0; i < 11; ++i) w[i] = std::exp(-((i - 5) * (i - 5)) / (2.0 * 1.5 * 1.5));
  const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  double ssim_sum = 0;
  long long windows = 0;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      if (!covered(x, y)) continue;
      double sw = 0, ma = 0, mb = 0;
      for (int dy = -5; dy <= 5; ++dy)
        for (int dx = -5; dx <= 5; ++dx) {
          int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
          double k = w[dx + 5] * w[dy + 5];
          sw += k, ma += k * ya[size_t(yy) * W + xx], mb += k * yb[size_t(yy) * W + xx];
        }
      ma /= sw, mb /= sw;
      double va = 0, vb = 0, cov = 0;
      for (int dy = -5; dy <= 5; ++dy)
        for (int dx = -5; dx <= 5; ++dx) {
          int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= W || yy >= H) continue;
          double k = w[dx + 5] * w[dy + 5] / sw;
          double da = ya[size_t(yy) * W + xx] - ma, db = yb[size_t(yy) * W + xx] - mb;
          va += k * da * da, vb += k * db * db, cov += k * da * db;
        }
      ssim_sum += ((2 * ma * mb + C1) * (2 * cov + C2)) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
      ++windows;
    }
  m.ssim = ssim_sum / double(windows);
  return m;
}

}  // namespace xval
