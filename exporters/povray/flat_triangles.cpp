#include "povray/flat_triangles.h"

#include <algorithm>
#include <cmath>

namespace xval {

namespace {

// A normal as POV-Ray's parser keeps it: normalised in double, stored as
// float (the text holds the double exactly: pov::num round-trips).
glm::dvec3 asParsed(const glm::dvec3& n) {
  const double len = std::sqrt(glm::dot(n, n));
  if (!(len > 0.0)) return glm::dvec3(1, 0, 0);  // the parser's stand-in for a zero normal
  return glm::dvec3(glm::vec3(n / len));
}

// The angle between two lines (either direction), accurate near 0.
double lineAngle(const glm::dvec3& a, const glm::dvec3& b) {
  const double s = glm::length(glm::cross(a, b)), c = std::abs(glm::dot(a, b));
  return std::atan2(s, c);
}

// How far the face normal of a triangle whose corners are float32-rounded
// can turn from the face normal of the corners before rounding (whatever
// program wrote the file computed its normals from those): each coordinate
// moves by at most 2^-24 |p|, so an edge by at most 2 sqrt(3) 2^-24 m (m the
// largest coordinate magnitude), and the cross product of two edges by
// that times their summed lengths; over |cross| that is the angle, to first
// order. A tiny triangle far from the origin turns the most.
double faceNormalRounding(const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3) {
  const double m = std::max({std::abs(p1.x), std::abs(p1.y), std::abs(p1.z), std::abs(p2.x), std::abs(p2.y),
                             std::abs(p2.z), std::abs(p3.x), std::abs(p3.y), std::abs(p3.z)});
  const glm::dvec3 e1 = p2 - p1, e2 = p3 - p1;
  const double cross = glm::length(glm::cross(e1, e2));
  return 2.0 * std::sqrt(3.0) * std::ldexp(m, -24) * (glm::length(e1) + glm::length(e2)) / cross;
}

}  // namespace

PovFlatTriangles povFlatTriangles(const TriangleMesh& mesh, double bound_rad) {
  constexpr double kPovEpsilon = 1e-10;  // POV-Ray 3.7's EPSILON
  PovFlatTriangles out;
  if (mesh.normals.size() != mesh.positions.size()) return out;  // no normals written: every triangle flat, by design
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const glm::dvec3 n1 = asParsed(mesh.normals[tri[0]]), n2 = asParsed(mesh.normals[tri[1]]),
                     n3 = asParsed(mesh.normals[tri[2]]);
    const glm::dvec3 d1 = n1 - n2, d2 = n1 - n3;
    if (glm::dot(d1, d1) > kPovEpsilon || glm::dot(d2, d2) > kPovEpsilon) continue;  // smooth
    ++out.flat;
    const glm::dvec3 p1 = mesh.positions[tri[0]], p2 = mesh.positions[tri[1]], p3 = mesh.positions[tri[2]];
    const glm::dvec3 face = glm::cross(p2 - p1, p3 - p1);
    if (!(glm::dot(face, face) > 0.0)) continue;  // degenerate: no face normal, nothing hit
    double angle = 0.0;
    for (const glm::dvec3& n : {mesh.normals[tri[0]], mesh.normals[tri[1]], mesh.normals[tri[2]]})
      angle = std::max(angle, lineAngle(face, n));
    if (angle > bound_rad + faceNormalRounding(p1, p2, p3)) ++out.off_face;
    if (angle > out.max_angle_rad) {
      out.max_angle_rad = angle;
      out.worst = t;
    }
  }
  return out;
}

}  // namespace xval
