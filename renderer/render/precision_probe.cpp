// The precision probes' per-sample math (render/precision_probe.h).
#include "render/precision_probe.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace xval {

BarycentricDerivatives barycentricDerivatives(const CameraRays& cam, const glm::dvec3 P[3], double b1, double b2,
                                              double step) {
  const glm::dvec3 P0 = P[0], e1 = P[1] - P0, e2 = P[2] - P0;
  const glm::dvec3 T = cam.origin - P0, a1 = glm::cross(e2, T), a2 = glm::cross(T, e1), mm = glm::cross(e2, e1);
  const glm::dvec3 to_p = P0 + b1 * e1 + b2 * e2 - cam.origin;
  const glm::dvec3 D = to_p / glm::dot(to_p, cam.forward);
  const double s = cam.tan_half_fov * step;
  const glm::dvec3 Dx = (2.0 / cam.width) * s * cam.aspect * cam.right, Dy = (-2.0 / cam.height) * s * cam.up;
  const double dm = glm::dot(D, mm), da1 = glm::dot(D, a1), da2 = glm::dot(D, a2);
  auto along = [&](const glm::dvec3& Dd) {
    const double dmd = glm::dot(Dd, mm);
    return glm::dvec2((glm::dot(Dd, a1) * dm - da1 * dmd) / (dm * dm), (glm::dot(Dd, a2) * dm - da2 * dmd) / (dm * dm));
  };
  return {along(Dx), along(Dy)};
}

glm::dvec2 planeBarycentrics(const CameraRays& cam, const glm::dvec3 P[3], double x, double y) {
  const glm::dvec3 P0 = P[0], e1 = P[1] - P0, e2 = P[2] - P0;
  const glm::dvec3 T = cam.origin - P0, D = cam.direction(x, y);
  const double dm = glm::dot(D, glm::cross(e2, e1));
  return glm::dvec2(glm::dot(D, glm::cross(e2, T)), glm::dot(D, glm::cross(T, e1))) / dm;
}

std::array<std::array<glm::dvec2, 2>, 4> quadUvDerivativeChoices(const CameraRays& cam, const glm::dvec3 P[3],
                                                                 const glm::dvec2 uv[3], double x, double y, int n) {
  const int gx = int(std::floor(x * n)) & ~1, gy = int(std::floor(y * n)) & ~1;
  auto uvAt = [&](int cx, int cy) {
    const glm::dvec2 b = planeBarycentrics(cam, P, (cx + 0.5) / n, (cy + 0.5) / n);
    return (1.0 - b.x - b.y) * uv[0] + b.x * uv[1] + b.y * uv[2];
  };
  const glm::dvec2 u00 = uvAt(gx, gy), u10 = uvAt(gx + 1, gy), u01 = uvAt(gx, gy + 1), u11 = uvAt(gx + 1, gy + 1);
  const glm::dvec2 dx[2] = {u10 - u00, u11 - u01}, dy[2] = {u01 - u00, u11 - u10};
  return {{{dx[0], dy[0]}, {dx[0], dy[1]}, {dx[1], dy[0]}, {dx[1], dy[1]}}};
}

ProjectedTriangle projectTriangle(const CameraRays& cam, const glm::dvec3 P[3]) {
  ProjectedTriangle t;
  for (int k = 0; k < 3; ++k) {
    double z = 0.0;
    t.c[size_t(k)] = projectToPixels(cam, P[k], &z);
    t.in_front = t.in_front && z > 0.0;
  }
  t.lo = glm::min(t.c[0], glm::min(t.c[1], t.c[2]));
  t.hi = glm::max(t.c[0], glm::max(t.c[1], t.c[2]));
  return t;
}

glm::dvec2 projectSample(const CameraRays& cam, double x, double y) {
  return projectScreenSample(cam, cam.screenX(x), cam.screenY(y));
}

glm::dvec2 projectScreenSample(const CameraRays& cam, double sx, double sy) {
  const glm::dvec3 d = cam.directionFromScreen(sx, sy);
  return projectToPixels(cam, cam.origin + d / glm::dot(d, cam.forward));
}

double segmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a, ap = p - a;
  const double len2 = glm::dot(ab, ab);
  const double f = len2 > 0.0 ? std::clamp(glm::dot(ap, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(ap - f * ab);
}

bool nearProjectedBoundary(const ProjectedTriangle& t, glm::dvec2 p, double within) {
  if (!t.in_front) return true;
  for (int k = 0; k < 3; ++k)
    if (segmentDistance(p, t.c[size_t(k)], t.c[size_t(k + 1) % 3]) <= within) return true;
  return false;
}

BoundaryNearness::BoundaryNearness(double w) : within(w) {
  if (!(w >= 0.0)) {  // negative or NaN: no distance is within it, no square either (dot(q, q) >= 0 or NaN)
    squared = -1.0;
    return;
  }
  double x = w * w;  // within an ulp or two of the bound: step to it
  while (x > 0.0 && !(std::sqrt(x) <= w)) x = std::nextafter(x, 0.0);
  for (double up = std::nextafter(x, HUGE_VAL); up != x && std::sqrt(up) <= w; up = std::nextafter(x, HUGE_VAL)) x = up;
  squared = x;
}

bool BoundaryNearness::segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) const {
  const glm::dvec2 ab = b - a, ap = p - a;
  const double len2 = glm::dot(ab, ab);
  double f = 0.0;
  if (len2 > 0.0) {
    const double t = glm::dot(ap, ab);
    if (!(len2 <= std::numeric_limits<double>::max()))
      f = std::clamp(t / len2, 0.0, 1.0);  // len2 infinite: t / len2 may be NaN, as segmentDistance's
    else if (!(t <= 0.0))
      f = t >= len2 ? 1.0 : std::clamp(t / len2, 0.0, 1.0);  // NaN t: as segmentDistance's
  }
  const glm::dvec2 q = ap - f * ab;
  return glm::dot(q, q) <= squared;
}

bool BoundaryNearness::operator()(const ProjectedTriangle& t, glm::dvec2 p) const {
  if (!t.in_front) return true;
  for (int k = 0; k < 3; ++k)
    if (segment(p, t.c[size_t(k)], t.c[size_t(k + 1) % 3])) return true;
  return false;
}

}  // namespace xval
