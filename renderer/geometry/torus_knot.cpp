#include "geometry/torus_knot.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/mesh.h"

namespace xval {

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// One double-reflection step (Wang, Juettler, Zheng, Liu 2008): transports
// normal n from (x0, t0) to (x1, t1).
glm::dvec3 transport(glm::dvec3 x0, glm::dvec3 t0, glm::dvec3 n, glm::dvec3 x1,
                     glm::dvec3 t1) {
  glm::dvec3 v1 = x1 - x0;
  double c1 = glm::dot(v1, v1);
  if (c1 == 0.0) return n;
  glm::dvec3 nl = n - (2.0 / c1) * glm::dot(v1, n) * v1;
  glm::dvec3 tl = t0 - (2.0 / c1) * glm::dot(v1, t0) * v1;
  glm::dvec3 v2 = t1 - tl;
  double c2 = glm::dot(v2, v2);
  glm::dvec3 out = c2 == 0.0 ? nl : nl - (2.0 / c2) * glm::dot(v2, nl) * v2;
  // Remove round-off drift: exactly orthogonal to t1, unit length.
  out -= glm::dot(out, t1) * t1;
  return glm::normalize(out);
}

glm::dvec3 rotateAbout(glm::dvec3 v, glm::dvec3 axis, double angle) {
  // Rodrigues, for v orthogonal to the unit axis.
  return std::cos(angle) * v + std::sin(angle) * glm::cross(axis, v);
}
}  // namespace

TorusKnotCurve::TorusKnotCurve(const TorusKnot& k, int grid_steps) : k_(k) {
  step_ = kTwoPi / grid_steps;
  grid_normals_.resize(grid_steps + 1);
  glm::dvec3 t0 = glm::normalize(derivative(0.0));
  glm::dvec3 seed = std::abs(t0.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
  grid_normals_[0] = glm::normalize(seed - glm::dot(seed, t0) * t0);
  for (int i = 0; i < grid_steps; ++i) {
    double a = i * step_, b = (i + 1) * step_;
    grid_normals_[i + 1] = transport(point(a), glm::normalize(derivative(a)), grid_normals_[i],
                                     point(b), glm::normalize(derivative(b)));
  }
  glm::dvec3 n0 = grid_normals_[0], n1 = grid_normals_[grid_steps];
  twist_ = std::atan2(glm::dot(glm::cross(n0, n1), t0), glm::dot(n0, n1));
}

glm::dvec3 TorusKnotCurve::point(double t) const {
  double rho = k_.major_radius + k_.minor_radius * std::cos(k_.q * t);
  return k_.center + glm::dvec3(rho * std::cos(k_.p * t), rho * std::sin(k_.p * t),
                                k_.minor_radius * std::sin(k_.q * t));
}

glm::dvec3 TorusKnotCurve::derivative(double t) const {
  double rho = k_.major_radius + k_.minor_radius * std::cos(k_.q * t);
  double drho = -k_.minor_radius * k_.q * std::sin(k_.q * t);
  double cp = std::cos(k_.p * t), sp = std::sin(k_.p * t);
  return {drho * cp - rho * k_.p * sp, drho * sp + rho * k_.p * cp,
          k_.minor_radius * k_.q * std::cos(k_.q * t)};
}

CurveFrame TorusKnotCurve::frame(double t) const {
  int steps = int(grid_normals_.size()) - 1;
  int i = std::clamp(int(std::floor(t / step_)), 0, steps - 1);
  double a = i * step_;
  CurveFrame f;
  f.point = point(t);
  f.tangent = glm::normalize(derivative(t));
  glm::dvec3 n = transport(point(a), glm::normalize(derivative(a)), grid_normals_[i], f.point,
                           f.tangent);
  // Undo the closing twist linearly in t: the frame at 2 pi equals that at 0.
  f.normal = rotateAbout(n, f.tangent, -twist_ * (t / kTwoPi));
  f.normal = glm::normalize(f.normal - glm::dot(f.normal, f.tangent) * f.tangent);
  f.binormal = glm::cross(f.tangent, f.normal);
  return f;
}

TriangleMesh tessellateTorusKnot(const TorusKnot& k) {
  TorusKnotCurve curve(k);
  const int na = k.segments_along, nr = k.segments_around;
  TriangleMesh m;
  const size_t nv = size_t(na + 1) * (nr + 1);
  m.positions.resize(nv);
  m.normals.resize(nv);
  m.uvs.resize(nv);
  auto idx = [nr](int i, int j) { return uint32_t(i * (nr + 1) + j); };
  for (int i = 0; i <= na; ++i) {
    // The last ring duplicates the first (same position and normal, u at
    // the end of the texture): the seam along the curve.
    int src = i == na ? 0 : i;
    CurveFrame f = curve.frame(kTwoPi * src / na);
    for (int j = 0; j <= nr; ++j) {
      int jsrc = j == nr ? 0 : j;  // seam around the tube
      double theta = kTwoPi * jsrc / nr;
      glm::dvec3 n = std::cos(theta) * f.normal + std::sin(theta) * f.binormal;
      m.normals[idx(i, j)] = n;
      m.positions[idx(i, j)] = f.point + k.tube_radius * n;
      m.uvs[idx(i, j)] = {k.uv_repeat.x * double(i) / na, k.uv_repeat.y * double(j) / nr};
    }
  }
  m.triangles.reserve(size_t(na) * nr * 2);
  for (int i = 0; i < na; ++i) {
    for (int j = 0; j < nr; ++j) {
      uint32_t a = idx(i, j), b = idx(i, j + 1), c = idx(i + 1, j + 1), d = idx(i + 1, j);
      // (around, along) order gives the outward normal.
      m.triangles.push_back({a, b, c});
      m.triangles.push_back({a, c, d});
    }
  }
  return m;
}

}  // namespace xval
