// Watertight ray-triangle intersection (Woop, Benthin, Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2013), written here in double precision
// for the reference path.
//
// The ray is sheared so it runs along +z; the triangle's 2D edge functions
// U, V, W at the origin are then evaluated with the same arithmetic on both
// triangles sharing an edge, so a ray through a shared edge hits at least
// one of them (no cracks). Barycentrics: hit = b0 p0 + b1 p1 + b2 p2 with
// (b0, b1, b2) = (U, V, W) / (U + V + W). Zero-area triangles never hit.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace xval {

struct RayShear {
  int kx, ky, kz;
  double sx, sy, sz;
  glm::dvec3 origin;

  RayShear() : kx(0), ky(1), kz(2), sx(0.0), sy(0.0), sz(1.0), origin(0.0) {}
  RayShear(glm::dvec3 o, glm::dvec3 d) : origin(o) {
    glm::dvec3 a = glm::abs(d);
    kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0.0) std::swap(kx, ky);  // keep the winding
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
  }
};

struct TriangleHit {
  double t, b1, b2;
};

// Two-sided. True when the ray hits the triangle at t in (t_min, t_max).
inline bool intersectTriangle(const RayShear& r, glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2,
                              double t_min, double t_max, TriangleHit& out) {
  const glm::dvec3 A = p0 - r.origin, B = p1 - r.origin, C = p2 - r.origin;
  const double ax = A[r.kx] - r.sx * A[r.kz], ay = A[r.ky] - r.sy * A[r.kz];
  const double bx = B[r.kx] - r.sx * B[r.kz], by = B[r.ky] - r.sy * B[r.kz];
  const double cx = C[r.kx] - r.sx * C[r.kz], cy = C[r.ky] - r.sy * C[r.kz];
  const double U = cx * by - cy * bx;
  const double V = ax * cy - ay * cx;
  const double W = bx * ay - by * ax;
  if ((U < 0.0 || V < 0.0 || W < 0.0) && (U > 0.0 || V > 0.0 || W > 0.0)) return false;
  const double det = U + V + W;
  if (det == 0.0) return false;
  const double az = r.sz * A[r.kz], bz = r.sz * B[r.kz], cz = r.sz * C[r.kz];
  const double t = (U * az + V * bz + W * cz) / det;
  if (!(t > t_min && t < t_max)) return false;
  out = {t, V / det, W / det};
  return true;
}

}  // namespace xval
