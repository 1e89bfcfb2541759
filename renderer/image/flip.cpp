// LDR-FLIP (image/flip.h states every step and constant, and its source).
#include "image/flip.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/glm.hpp>

#include "image/compare.h"
#include "image/perceptual.h"

namespace xval {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The paper's constants (flip.h).
struct CsfFit {
  double a1, b1, a2, b2;
};
constexpr CsfFit kCsfAchromatic{1.0, 0.0047, 0.0, 1e-5};
constexpr CsfFit kCsfRedGreen{1.0, 0.0053, 0.0, 1e-5};
constexpr CsfFit kCsfBlueYellow{34.1, 0.04, 13.5, 0.025};
constexpr double kCsfWidestB = 0.04;
constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95;
constexpr double kFeatureWidthDegrees = 0.082;  // q_f = 0.5: the square root below

// One plane of doubles, row by row.
struct Grid {
  int w = 0, h = 0;
  std::vector<double> v;
  Grid(int w_, int h_) : w(w_), h(h_), v(size_t(w_) * h_, 0.0) {}
  double& at(int x, int y) { return v[size_t(y) * w + x]; }
  double at(int x, int y) const { return v[size_t(y) * w + x]; }
};

// A symmetric 1-D kernel of taps k[0 .. 2r] for offsets -r .. r.
using Kernel = std::vector<double>;

// Separable convolution: kx along x, then ky along y, edge pixels repeated.
// Each pass copies its line into a buffer padded with the edge values, so
// the inner loop has no bounds to check.
Grid convolve(const Grid& in, const Kernel& kx, const Kernel& ky) {
  const int rx = int(kx.size() / 2), ry = int(ky.size() / 2);
  Grid tmp(in.w, in.h), out(in.w, in.h);
  auto pass = [](const double* src, size_t stride, int n, const Kernel& k, int r, std::vector<double>& line,
                 double* dst) {
    for (int i = 0; i < n + 2 * r; ++i) line[size_t(i)] = src[size_t(std::clamp(i - r, 0, n - 1)) * stride];
    const double* kk = k.data();
    for (int x = 0; x < n; ++x) {
      const double* l = &line[size_t(x)];
      double s = 0.0;
      for (int i = 0; i <= 2 * r; ++i) s += kk[i] * l[i];
      dst[size_t(x) * stride] = s;
    }
  };
  std::vector<double> line(size_t(std::max(in.w + 2 * rx, in.h + 2 * ry)));
  for (int y = 0; y < in.h; ++y) pass(&in.v[size_t(y) * in.w], 1, in.w, kx, rx, line, &tmp.v[size_t(y) * in.w]);
  for (int x = 0; x < in.w; ++x) pass(&tmp.v[size_t(x)], size_t(in.w), in.h, ky, ry, line, &out.v[size_t(x)]);
  return out;
}

// exp(-pi^2 x^2 / b) at x = i / ppd degrees, i in [-r, r].
Kernel csfGaussian(double b, int r, double ppd) {
  Kernel k(size_t(2 * r + 1));
  for (int i = -r; i <= r; ++i) {
    const double x = double(i) / ppd;
    k[size_t(i + r)] = std::exp(-kPi * kPi * x * x / b);
  }
  return k;
}

double sum(const Kernel& k) {
  double s = 0.0;
  for (double v : k) s += v;
  return s;
}

Kernel scaled(Kernel k, double f) {
  for (double& v : k) v *= f;
  return k;
}

// The channel convolved with its CSF's 2-D kernel normalised to sum 1:
// s(x, y) = c1 g1(x) g1(y) + c2 g2(x) g2(y), c = a sqrt(pi / b), whose sum
// is c1 S1^2 + c2 S2^2 (S: the 1-D sum).
Grid csfFilter(const Grid& in, const CsfFit& f, double ppd) {
  const int r = int(std::ceil(3.0 * std::sqrt(kCsfWidestB / (2.0 * kPi * kPi)) * ppd));
  const Kernel g1 = csfGaussian(f.b1, r, ppd);
  const double c1 = f.a1 * std::sqrt(kPi / f.b1), s1 = sum(g1);
  if (f.a2 == 0.0) return convolve(in, scaled(g1, 1.0 / s1), scaled(g1, 1.0 / s1));
  const Kernel g2 = csfGaussian(f.b2, r, ppd);
  const double c2 = f.a2 * std::sqrt(kPi / f.b2), s2 = sum(g2);
  const double total = c1 * s1 * s1 + c2 * s2 * s2;
  const double w1 = c1 * s1 * s1 / total, w2 = c2 * s2 * s2 / total;
  Grid p1 = convolve(in, scaled(g1, 1.0 / s1), scaled(g1, 1.0 / s1));
  const Grid p2 = convolve(in, scaled(g2, 1.0 / s2), scaled(g2, 1.0 / s2));
  for (size_t i = 0; i < p1.v.size(); ++i) p1.v[i] = w1 * p1.v[i] + w2 * p2.v[i];
  return p1;
}

// The feature kernels (flip.h): the Gaussian (sum 1), its first and second
// derivatives (positive weights sum 1, negative weights -1).
struct FeatureKernels {
  Kernel g, d1, d2;
};
Kernel normalisedSigned(Kernel k) {
  double pos = 0.0, neg = 0.0;
  for (double v : k) (v > 0 ? pos : neg) += v;
  for (double& v : k) v = v > 0 ? v / pos : (v < 0 ? v / -neg : 0.0);
  return k;
}
FeatureKernels featureKernels(double ppd) {
  const double sigma = 0.5 * kFeatureWidthDegrees * ppd;
  const int r = int(std::ceil(3.0 * sigma));
  FeatureKernels f;
  f.g.resize(size_t(2 * r + 1)), f.d1.resize(f.g.size()), f.d2.resize(f.g.size());
  for (int i = -r; i <= r; ++i) {
    const double x = double(i), g = std::exp(-x * x / (2.0 * sigma * sigma));
    f.g[size_t(i + r)] = g;
    f.d1[size_t(i + r)] = -x / (sigma * sigma) * g;
    f.d2[size_t(i + r)] = (x * x / (sigma * sigma) - 1.0) / (sigma * sigma) * g;
  }
  f.g = scaled(f.g, 1.0 / sum(f.g));
  f.d1 = normalisedSigned(f.d1);
  f.d2 = normalisedSigned(f.d2);
  return f;
}

// |(response along x, response along y)| of the derivative kernel d.
Grid detector(const Grid& y, const Kernel& d, const Kernel& g) {
  const Grid gx = convolve(y, d, g), gy = convolve(y, g, d);
  Grid out(y.w, y.h);
  for (size_t i = 0; i < out.v.size(); ++i) out.v[i] = std::sqrt(gx.v[i] * gx.v[i] + gy.v[i] * gy.v[i]);
  return out;
}

// The colour as an sRGB code in [0, 1] over black.
glm::dvec3 code(const Image& img, size_t i) {
  const float* p = &img.rgba[i * 4];
  return {std::clamp(double(p[0]), 0.0, 1.0), std::clamp(double(p[1]), 0.0, 1.0),
          std::clamp(double(p[2]), 0.0, 1.0)};
}

glm::dvec3 huntLab(glm::dvec3 linear) {
  const glm::dvec3 lab = xyzToLab(linearSrgbToXyz(glm::clamp(linear, 0.0, 1.0)));
  return {lab.x, 0.01 * lab.x * lab.y, 0.01 * lab.x * lab.z};
}

double hyab(glm::dvec3 p, glm::dvec3 q) {
  const double da = p.y - q.y, db = p.z - q.z;
  return std::abs(p.x - q.x) + std::sqrt(da * da + db * db);
}

void requireViewingDistance(double ppd) {
  if (!(ppd > 0.0) || !std::isfinite(ppd))
    throw std::invalid_argument("FLIP: pixels per degree " + std::to_string(ppd) + ": expected a finite number > 0");
}

}  // namespace

FlipImage flipImage(const Image& img, double ppd) {
  requireViewingDistance(ppd);
  const FeatureKernels fk = featureKernels(ppd);
  const int w = img.width, h = img.height;
  const size_t n = size_t(w) * h;
  Grid yy(w, h), cx(w, h), cz(w, h), achromatic(w, h);
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec3 c = code(img, i);
    const glm::dvec3 xyz = linearSrgbToXyz({srgbDecode(c.r), srgbDecode(c.g), srgbDecode(c.b)});
    const double xr = xyz.x / kD65White[0], yr = xyz.y / kD65White[1], zr = xyz.z / kD65White[2];
    yy.v[i] = 116.0 * yr - 16.0, cx.v[i] = 500.0 * (xr - yr), cz.v[i] = 200.0 * (yr - zr);
    achromatic.v[i] = yr;
  }
  const Grid fy = csfFilter(yy, kCsfAchromatic, ppd), fx = csfFilter(cx, kCsfRedGreen, ppd),
              fz = csfFilter(cz, kCsfBlueYellow, ppd);
  FlipImage out;
  out.width = w, out.height = h, out.pixels_per_degree = ppd;
  out.hunt_lab.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const double yr = (fy.v[i] + 16.0) / 116.0, xr = fx.v[i] / 500.0 + yr, zr = yr - fz.v[i] / 200.0;
    const glm::dvec3 xyz(xr * kD65White[0], yr * kD65White[1], zr * kD65White[2]);
    out.hunt_lab[i] = huntLab(xyzToLinearSrgb(xyz));
  }
  out.edge = std::move(detector(achromatic, fk.d1, fk.g).v);
  out.point = std::move(detector(achromatic, fk.d2, fk.g).v);
  return out;
}

std::vector<float> flipErrorMap(const Image& a, const Image& b, double ppd) {
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("FLIP: image sizes differ (" + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height) + ")");
  return flipErrorMap(flipImage(a, ppd), flipImage(b, ppd));
}

std::vector<float> flipErrorMap(const FlipImage& pa, const FlipImage& pb) {
  if (pa.width != pb.width || pa.height != pb.height || pa.pixels_per_degree != pb.pixels_per_degree)
    throw std::invalid_argument("FLIP: the two images' FLIP planes differ in size or viewing distance");
  static const double c_max =
      std::pow(hyab(huntLab({0.0, 1.0, 0.0}), huntLab({0.0, 0.0, 1.0})), kQc);
  const size_t n = size_t(pa.width) * pa.height;
  std::vector<float> map(n);
  for (size_t i = 0; i < n; ++i) {
    const double e = std::pow(hyab(pa.hunt_lab[i], pb.hunt_lab[i]), kQc);
    const double colour = e < kPc * c_max ? e * kPt / (kPc * c_max)
                                          : kPt + (e - kPc * c_max) / (c_max - kPc * c_max) * (1.0 - kPt);
    const double df = std::max(std::abs(pa.edge[i] - pb.edge[i]), std::abs(pa.point[i] - pb.point[i]));
    const double feature = std::sqrt(df / std::sqrt(2.0));  // ^q_f, q_f = 0.5
    map[i] = float(std::pow(colour, 1.0 - feature));
  }
  return map;
}

FlipMetrics flipSummary(const std::vector<float>& map, const Image& a, const Image& b) {
  const size_t n = size_t(a.width) * a.height;
  if (map.size() != n || b.width != a.width || b.height != a.height)
    throw std::invalid_argument("FLIP: the error map and the images differ in size");
  std::vector<double> covered;
  covered.reserve(n);
  double total = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!(a.rgba[i * 4 + 3] > 0.0f) && !(b.rgba[i * 4 + 3] > 0.0f)) continue;
    covered.push_back(map[i]);
    total += map[i];
  }
  FlipMetrics m;
  m.pixels = (long long)covered.size();
  if (covered.empty()) return m;
  m.mean = total / double(covered.size());
  m.p99 = nearestRankPercentile(std::move(covered), 0.99);
  return m;
}

FlipMetrics flipMetrics(const Image& a, const Image& b, double ppd) {
  return flipSummary(flipErrorMap(a, b, ppd), a, b);
}

}  // namespace xval
