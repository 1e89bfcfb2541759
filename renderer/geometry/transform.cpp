#include "geometry/transform.h"

#include <cmath>
#include <utility>

namespace xval {

namespace {
constexpr double kPi = 3.14159265358979323846;

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

std::string str(glm::dvec3 v) {
  return "[" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + "]";
}
}  // namespace

glm::dmat3 rotationMatrix(const Rotation& r) {
  if (!finite(r.axis)) throw TransformError("rotate.axis: " + str(r.axis) + " is not finite");
  const double len = glm::length(r.axis);
  if (!(len > 0.0) || !std::isfinite(len))
    throw TransformError("rotate.axis: " + str(r.axis) + " has no direction (expected a non-zero vector)");
  if (!std::isfinite(r.angle_deg))
    throw TransformError("rotate.angle_deg: " + std::to_string(r.angle_deg) + " is not finite");
  const glm::dvec3 u = r.axis / len;
  const double a = r.angle_deg * (kPi / 180.0), c = std::cos(a), s = std::sin(a), k = 1.0 - c;
  // Rodrigues, written out row by row; glm takes columns.
  const glm::dmat3 rows(c + k * u.x * u.x, k * u.x * u.y - s * u.z, k * u.x * u.z + s * u.y,
                        k * u.y * u.x + s * u.z, c + k * u.y * u.y, k * u.y * u.z - s * u.x,
                        k * u.z * u.x - s * u.y, k * u.z * u.y + s * u.x, c + k * u.z * u.z);
  return glm::transpose(rows);
}

Affine toAffine(const ObjectTransform& t) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(t.scale[i]) || t.scale[i] == 0.0)
      throw TransformError("scale[" + std::to_string(i) + "]: " + std::to_string(t.scale[i]) +
                           " (expected a finite non-zero number)");
  if (!finite(t.translate)) throw TransformError("translate: " + str(t.translate) + " is not finite");
  glm::dmat3 s(0.0);
  s[0][0] = t.scale.x, s[1][1] = t.scale.y, s[2][2] = t.scale.z;
  return {rotationMatrix(t.rotate) * s, t.translate};
}

TriangleMesh transformed(const TriangleMesh& mesh, const Affine& f) {
  const double det = f.determinant();
  if (!std::isfinite(det) || det == 0.0 || !finite(f.offset))
    throw TransformError("transform: the matrix is singular or not finite (determinant " + std::to_string(det) +
                         ")");
  const glm::dmat3 normal_map = glm::transpose(glm::inverse(f.linear));  // A^-T
  TriangleMesh out;
  out.positions.reserve(mesh.positions.size());
  out.normals.reserve(mesh.normals.size());
  for (const auto& p : mesh.positions) out.positions.push_back(f.point(p));
  for (const auto& n : mesh.normals) out.normals.push_back(glm::normalize(normal_map * n));
  out.uvs = mesh.uvs;
  out.triangles = mesh.triangles;
  if (det < 0.0)
    for (auto& t : out.triangles) std::swap(t.y, t.z);
  return out;
}

}  // namespace xval
