#include "geometry/front_faces.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <variant>

#include "geometry/closed_surface.h"
#include "geometry/torus_knot.h"

namespace xval {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// How far rounding to float32 may have moved a vertex (tessellate() rounds
// every coordinate): 2^-24 of the largest coordinate, per coordinate; this
// returns twice that, a bound on the distance moved.
double roundingScale(const TriangleMesh& m) {
  double largest = 0.0;
  for (const auto& p : m.positions) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return largest * 0x1p-23;
}

// Condition 2: the winding agrees with the vertex normals everywhere, and
// rounding has not distorted the mesh: every edge is longer than 1000 x
// the rounding scale (a small object far from the origin collapses onto
// the float grid, with zero-area triangles and coincident twins: not the
// surface of a solid any more).
bool windingAgreesWithNormals(const TriangleMesh& m, double rounding) {
  for (const auto& t : m.triangles) {
    const glm::dvec3 a = m.positions[t[0]], b = m.positions[t[1]], c = m.positions[t[2]];
    if (!(std::min({glm::length(b - a), glm::length(c - b), glm::length(a - c)}) > 1e3 * rounding))
      return false;
    const glm::dvec3 g = glm::cross(b - a, c - a);
    if (!(glm::dot(g, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]) > 0.0)) return false;
  }
  return !m.triangles.empty();
}

// Radius of the circle through a, b, c (infinite when collinear).
double circumradius(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
  const double la = glm::length(b - c), lb = glm::length(a - c), lc = glm::length(a - b);
  const double twice_area = glm::length(glm::cross(b - a, c - a));
  return twice_area > 0.0 ? la * lb * lc / (2.0 * twice_area) : std::numeric_limits<double>::infinity();
}

bool eyeOutside(const UvSphere& s, glm::dvec3 eye, double rounding) {
  return glm::length(eye - s.center) > s.radius * (1.0 + 1e-6) + rounding;
}

bool eyeOutside(const TorusKnot& k, glm::dvec3 eye, double rounding) {
  const TorusKnotCurve curve(k, 1 << 10);  // only point() is used: the frame grid is not
  const int n = k.segments_along;
  if (n < 3) return false;
  auto c = [&](int i) { return curve.point(kTwoPi * double(((i % n) + n) % n) / n); };
  double nearest = std::numeric_limits<double>::infinity(), chord = 0.0;
  double min_circumradius = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const glm::dvec3 a = c(i - 1), b = c(i), d = c(i + 1);
    nearest = std::min(nearest, glm::length(eye - b));
    chord = std::max(chord, glm::length(d - b));
    min_circumradius = std::min(min_circumradius, circumradius(a, b, d));
  }
  // float32 vertices: moved by at most `rounding`; and some slack.
  const double extent = glm::length(k.center) + k.major_radius + k.minor_radius + k.tube_radius;
  const double margin = 1e-6 * extent + rounding;
  return k.tube_radius < 0.99 * min_circumradius && nearest > k.tube_radius + chord + margin;
}

bool eyeOutside(const Plane&, glm::dvec3, double) { return false; }  // open: its back is visible
// A model file is not known to bound a solid (it may be open, or have
// holes or inconsistent winding): never.
bool eyeOutside(const MeshFile&, glm::dvec3, double) { return false; }

}  // namespace

bool backFacesNeverFirstHit(const Shape& shape, const TriangleMesh& mesh, glm::dvec3 eye) {
  const double rounding = roundingScale(mesh);
  const bool outside = std::visit([&](const auto& s) { return eyeOutside(s, eye, rounding); }, shape);
  return outside && windingAgreesWithNormals(mesh, rounding);
}

bool eyeOutsideBox(const TriangleMesh& mesh, glm::dvec3 eye) {
  glm::dvec3 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return eye.x < lo.x || eye.y < lo.y || eye.z < lo.z || eye.x > hi.x || eye.y > hi.y || eye.z > hi.z;
}

bool closedMeshBackFacesNeverFirstHit(const TriangleMesh& mesh, glm::dvec3 eye) {
  return eyeOutsideBox(mesh, eye) && whyNotAnOutwardSolid(mesh).empty();  // condition C (cheap) first
}

bool objectBackFacesNeverFirstHit(const SceneObject& object, const TriangleMesh& mesh, glm::dvec3 eye) {
  if (std::holds_alternative<MeshFile>(object.shape)) return closedMeshBackFacesNeverFirstHit(mesh, eye);
  return object.transform.isIdentity() && backFacesNeverFirstHit(object.shape, mesh, eye);
}

bool facesAwayFromEye(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 p2, glm::dvec3 eye) {
  const glm::dvec3 g = glm::cross(p1 - p0, p2 - p0), e = eye - p0;
  return !(glm::dot(g, e) >= -1e-9 * glm::length(g) * glm::length(e));  // condition 3
}

std::vector<uint32_t> trianglesNotFacingAway(const TriangleMesh& m, glm::dvec3 eye) {
  std::vector<uint32_t> kept;
  for (uint32_t t = 0; t < m.triangles.size(); ++t) {
    const glm::u32vec3& v = m.triangles[t];
    if (!facesAwayFromEye(m.positions[v[0]], m.positions[v[1]], m.positions[v[2]], eye)) kept.push_back(t);
  }
  return kept;
}

}  // namespace xval
