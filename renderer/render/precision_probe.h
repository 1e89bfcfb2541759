// Precision probes: how much another renderer's rounding may change a
// pixel, measured by the reference renderer on its own samples
// (diagnostics only; the channels are image/image.h's kProbeChannels).
//
// The theorem each probe rests on: if a renderer's value x' of a quantity
// the shading reads differs from the reference's x by at most a step s
// along a direction e, and the saturated colour f is monotone along e over
// that step (true of every model and filter where no clamp, no texel pick
// and no mip level boundary lies inside the step), then
//   |f(x') - f(x)| <= max(|f(x + s e) - f(x)|, |f(x - s e) - f(x)|),
// so the largest change over the probed steps (both signs, each direction)
// bounds what that rounding can do to the sample. A pixel's bound is the
// box filter of its samples' (sum / n^2, as its colour is filtered): a
// sample moves the pixel by at most its own change / n^2.
//
// The steps, each the largest rounding among the renderers of its quantity:
//   kPositionStepPixels  2^-8 px: a rasteriser's sub-pixel grid (gl and
//                        EEVEE snap vertices to it: camera/triangle_edge.h),
//                        which moves where on the triangle a pixel samples;
//   kUvStepTexels        1/256 texel: a GPU's bilinear weights are 8-bit
//                        fractions of a texel;
//   kNormalStepRadians   2^-9 rad: a 10-bit signed normal (a GPU's packed
//                        normal) rounds each component by <= 1/1022, so the
//                        direction by <= sqrt(3)/1022 < 2^-9;
//   kLodStep             0.05 level: llvmpipe takes log2 of the footprint
//                        with a piecewise-linear approximation
//                        (lp_build_fast_log2), off by up to 0.043 of a
//                        level (docs/precision-models.md, "LOD"), beyond
//                        the 8-bit fraction it keeps.
//
// The formulas:
//   position: the hit p = P0 + b1 e1 + b2 e2 moved by s px along the
//     image's x or y stays on its triangle's plane with barycentrics
//     b + s db/dx (b + s db/dy), db/dx, db/dy from the camera ray's
//     differentials (barycentricDerivatives below); p, N, uv, V, L follow
//     (Gouraud: the interpolated vertex colours; flat: the face normal
//     stays);
//   uv: uv +- (kUvStepTexels / W, 0) and uv +- (0, kUvStepTexels / H), W x H
//     the level-0 texture; for a trilinear texture also lambda +- dl,
//     dl = kLodStep + max |lambda_quad - lambda|, lambda_quad the levels
//     a GPU may take from 2x2-quad finite differences
//     (quadUvDerivativeChoices below);
//   normal: N turned by kNormalStepRadians about either of two unit axes
//     a perpendicular to it: N' = cos(s) N + sin(s) (a x N) (N's length
//     kept; turnAxes below);
//   backfacing flip: the sample shaded with -N where N.V < 0.
// Every probe shades with the sample's own function and precision
// (render/renderer.cpp shadeHit), so an unperturbed probe is the sample's
// colour bit for bit.
//
// Edge fraction (the first hit a renderer's rounding may change): a
// sample's image-plane point within kTriangleEdgePixels (image/
// pixel_classes.h) of the projected boundary (the three edge segments) of a
// triangle that a sample of its pixel or of the 8 neighbours hit
// (nearProjectedBoundary below).
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <vector>

#include "camera/camera.h"
#include "camera/triangle_edge.h"

namespace xval {

inline constexpr double kPositionStepPixels = 1.0 / 256.0;
inline constexpr double kUvStepTexels = 1.0 / 256.0;
inline constexpr double kNormalStepRadians = 1.0 / 512.0;
inline constexpr double kLodStep = 0.05;

// The derivatives of a point's barycentrics (b1, b2) on the plane of the
// triangle P0 P1 P2 along the image's x and y, per `step` pixels. The ray
// through image point (x, y) is O + t D with D = forward + sx right + sy up'
// (camera/camera.h, D . forward = 1), so
//   dD/dx = (2 / W) tan(fov_y / 2) (W / H) right,  dD/dy = -(2 / H) tan(fov_y / 2) up'.
// On the plane (P0 + b1 e1 + b2 e2, e_k = P_k - P0, T = O - P0)
//   b1 = (D . a1) / (D . m), b2 = (D . a2) / (D . m),
//   a1 = e2 x T, a2 = T x e1, m = e2 x e1 (Cramer's rule, as Moller-Trumbore),
// whose derivative along x is db1/dx = ((Dx . a1)(D . m) - (D . a1)(Dx . m)) / (D . m)^2
// (the same for b2 and y). In double; D from the point p = P0 + b1 e1 +
// b2 e2: D = (p - O) / ((p - O) . forward).
struct BarycentricDerivatives {
  glm::dvec2 dx{0}, dy{0};  // (db1, db2) per step along x, along y
};
BarycentricDerivatives barycentricDerivatives(const CameraRays& cam, const glm::dvec3 P[3], double b1, double b2,
                                              double step);

// The barycentrics (b1, b2) where the camera ray through image point
// (x, y) meets the plane of P0 P1 P2 (Cramer's rule as above; not clipped
// to the triangle: a quad partner's ray may leave it, as a GPU's helper
// pixel extrapolates).
glm::dvec2 planeBarycentrics(const CameraRays& cam, const glm::dvec3 P[3], double x, double y);

// A GPU's uv derivatives at a sample: the sample grid is taken as the
// GPU's pixels (gl renders n x n samples as an n-times larger frame), the
// sample at grid column gx = floor(x n), row gy = floor(y n) (x, y its
// image point; n samples per pixel side) sits in the 2x2 quad of even
// (gx, gy), and the differences are those of the exact perspective uv
// (planeBarycentrics, uv = b0 uv0 + b1 uv1 + b2 uv2) at the quad's grid
// centres, per grid step. The (duv/dx, duv/dy) pairs a GPU may take for
// the whole quad holding that sample: the x difference of either row and the y difference of either
// column, in all four combinations. A driver that computes one level of
// detail per quad takes them at the quad's first pixel, which the window
// origin decides (OpenGL's is at the bottom, the image's row 0 at the top);
// one that computes it per pixel takes the pixel's own row and column, one
// of the four. llvmpipe computes one per quad (docs/precision-models.md,
// "LOD"). The probe takes the farthest of their levels from the exact one.
std::array<std::array<glm::dvec2, 2>, 4> quadUvDerivativeChoices(const CameraRays& cam, const glm::dvec3 P[3],
                                                                 const glm::dvec2 uv[3], double x, double y, int n);

// Two unit axes perpendicular to n (n not zero): a1 = normalize(n x e),
// e the coordinate axis least aligned with n, and a2 = normalize(n x a1).
template <class T> std::array<glm::vec<3, T>, 2> turnAxes(glm::vec<3, T> n) {
  using V = glm::vec<3, T>;
  const V m = glm::abs(n);
  const V e = m.x <= m.y && m.x <= m.z ? V(1, 0, 0) : m.y <= m.z ? V(0, 1, 0) : V(0, 0, 1);
  const V a1 = glm::normalize(glm::cross(n, e));
  return {a1, glm::normalize(glm::cross(n, a1))};
}

// The largest channel difference |a_c - b_c|.
template <class T> T largestChannelDifference(glm::vec<3, T> a, glm::vec<3, T> b) {
  const glm::vec<3, T> d = glm::abs(a - b);
  return std::max(d.x, std::max(d.y, d.z));
}

// A triangle projected to the image plane (camera/triangle_edge.h's
// projectToPixels, whose shift is common to every point it projects).
// in_front false: a corner is not in front of the camera (depth <= 0), its
// projection meaningless: such a triangle counts as near every sample (a
// possible false failure, never a false pass).
// lo, hi: the corners' bounding box (component-wise min and max).
struct ProjectedTriangle {
  std::array<glm::dvec2, 3> c;
  bool in_front = true;
  glm::dvec2 lo{0}, hi{0};
};
ProjectedTriangle projectTriangle(const CameraRays& cam, const glm::dvec3 P[3]);

// The sample at image point (x, y), projected as the triangles are: the
// point at depth 1 along its ray, cam.origin + direction(x, y) /
// (direction . forward).
glm::dvec2 projectSample(const CameraRays& cam, double x, double y);
// The same from the point's screen coordinates sx = cam.screenX(x), sy =
// cam.screenY(y) (bit-identical to projectSample(cam, x, y)), for a caller
// that projects many points of the same columns and rows.
glm::dvec2 projectScreenSample(const CameraRays& cam, double sx, double sy);

// Distance from p to the segment a b.
double segmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b);

// True when p lies within `within` pixels of one of t's three edge
// segments (or t is not in front of the camera).
bool nearProjectedBoundary(const ProjectedTriangle& t, glm::dvec2 p, double within);

// The same test, faster, for a caller testing many points against one
// distance: segmentDistance(p, a, b) <= within decided without its square
// root and, where the clamp decides the nearest point (an end of the
// segment), without its division, with the same result for every p, a, b.
// sqrt is correctly rounded and so non-decreasing: sqrt(x) <= within holds
// exactly for x <= squared, the largest double for which it holds; and
// f = clamp(t / len2, 0, 1) is 0 for t <= 0 (a zero f of either sign moves
// no coordinate's magnitude) and 1 for t >= len2 (len2 > 0).
struct BoundaryNearness {
  double within = 0.0, squared = 0.0;
  explicit BoundaryNearness(double within);
  bool segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) const;
  bool operator()(const ProjectedTriangle& t, glm::dvec2 p) const;  // nearProjectedBoundary
};

}  // namespace xval
