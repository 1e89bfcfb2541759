// How close a camera ray's hit is to another triangle: the distance, in
// the image plane and in pixels, of the hit from the nearest edge of the
// triangle it hit.
//
// Why pixels: a renderer that decides which of two triangles sharing an
// edge a ray or a pixel sample belongs to may decide differently from the
// reference when the sample lies within its rounding of the edge, and
// take the neighbouring triangle's colour (another flat normal, another
// texel), or miss through a crack between them (docs/pixel-classes.md,
// "Triangle edge"). The largest such rounding among the renderers is a
// rasteriser's, and it is a screen-space quantity:
//   - gl and EEVEE (Mesa llvmpipe; a GPU alike) snap each projected vertex
//     to a fixed-point grid of 2^-8 pixel (8 sub-pixel bits), moving it
//     by at most 2^-9 per axis, so by at most 2^-9 sqrt(2) in the image
//     plane. The edge between two snapped vertices is, at every point, a
//     convex combination of their moves: it moves by at most
//     2^-9 sqrt(2) = 0.0028 px. The float32 vertex transform before the
//     snap adds a few roundings of the window coordinates (2^-24 x a few
//     hundred pixels, ~1e-5 px): bound, 2^-8 px (kTriangleEdgePixels in
//     image/pixel_classes.h).
//   - POV-Ray's mesh test puts the hit on a plane built from the float32
//     unit normal, which moves the hit by about one float32 rounding of the
//     corner coordinates, s = 2^-24 max_k |P_k| (measured on its crack,
//     docs/pixel-classes.md); seen from distance z through a focal length
//     of f pixels that is s f / z pixels: ~1e-4 px for the reference
//     scenes' s ~ 1e-7, f ~ 600, z >= 1, inside the rasteriser's bound.
//
// The math. The hit p (barycentrics b0, b1, b2 of the triangle P0 P1 P2),
// for each edge line U V (opposite vertex k): q = U + ((p - U) . e) e with
// e = (V - U) / |V - U|, the foot of p on the line, and a second point of
// the line, q' = q + L e (L = 1e-3 of p's depth, so q' lies in front of the
// camera wherever p does). The pinhole projection pi (camera/camera.h:
// pi(P) = k (d . right, d . up) / (d . forward), d = P - eye,
// k = H / (2 tan(fov_y / 2)) pixels per unit of the image plane, the same
// along both axes) maps the line to the line through pi(q), pi(q'), and
// the result is the distance of pi(p) from it:
//   |(pi(q') - pi(q)) x (pi(p) - pi(q))| / |pi(q') - pi(q)|,
// minimised over the three edges (for a point inside a triangle the
// nearest boundary point lies on the nearest edge line). An edge seen end
// on (|pi(q') - pi(q)| below 1e-12 of its size) counts as a point: |pi(p) -
// pi(q)|. All in double: the distances that matter (1e-8 world units,
// 1e-6 px) are many orders above double's rounding of coordinates near 1.
#pragma once

#include <glm/glm.hpp>

#include "image/channel_sentinels.h"

#include <algorithm>
#include <cmath>

#include "camera/camera.h"

namespace xval {

// p's position in the image plane, in pixels (up to a shift that cancels);
// depth: p's distance along the camera's forward axis.
inline glm::dvec2 projectToPixels(const CameraRays& cam, glm::dvec3 p, double* depth = nullptr) {
  const glm::dvec3 d = p - cam.origin;
  const double z = glm::dot(d, cam.forward);
  if (depth) *depth = z;
  const double k = cam.height / (2.0 * cam.tan_half_fov);
  return k * glm::dvec2(glm::dot(d, cam.right), glm::dot(d, cam.up)) / z;
}

// P[3]: the triangle's corners (double, as traced); b1, b2: the hit's
// barycentrics of P[1], P[2].
inline double triangleEdgePixels(const CameraRays& cam, const glm::dvec3 P[3], double b1, double b2) {
  const glm::dvec3 p = (1.0 - b1 - b2) * P[0] + b1 * P[1] + b2 * P[2];
  double z = 0.0;
  const glm::dvec2 pp = projectToPixels(cam, p, &z);
  if (!(z > 0.0)) return kFarFromTriangleEdge;
  double best = kFarFromTriangleEdge;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec3 U = P[(k + 1) % 3], V = P[(k + 2) % 3];
    const double len = glm::length(V - U);
    if (!(len > 0.0)) continue;
    const glm::dvec3 e = (V - U) / len;
    const glm::dvec3 q = U + glm::dot(p - U, e) * e;
    const glm::dvec2 a = projectToPixels(cam, q), b = projectToPixels(cam, q + 1e-3 * z * e);
    const glm::dvec2 ab = b - a, ap = pp - a;
    const double ab_len = glm::length(ab);
    const double d = ab_len > 1e-12 * (glm::length(a) + 1.0) ? std::abs(ab.x * ap.y - ab.y * ap.x) / ab_len
                                                             : glm::length(ap);
    if (std::isfinite(d)) best = std::min(best, d);
  }
  return best;
}

}  // namespace xval
