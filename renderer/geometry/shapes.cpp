// Sphere and plane tessellation, and the shape dispatch.
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "geometry/float_rounding.h"
#include "geometry/mesh.h"

namespace xval {

namespace {
}

// Latitude j = 0 is the +y pole, longitude i = 0 faces +z. uv = (i/nlon,
// j/nlat) * repeat, so v runs from the top pole down, as the image does.
TriangleMesh tessellateSphere(const UvSphere& s) {
  const int nlon = s.segments_longitude, nlat = s.segments_latitude;
  TriangleMesh m;
  auto idx = [nlon](int i, int j) { return uint32_t(j * (nlon + 1) + i); };
  for (int j = 0; j <= nlat; ++j) {
    double theta = std::numbers::pi * j / nlat;
    double st = j == 0 || j == nlat ? 0.0 : std::sin(theta);
    double ct = j == 0 ? 1.0 : j == nlat ? -1.0 : std::cos(theta);
    for (int i = 0; i <= nlon; ++i) {
      double phi = 2.0 * std::numbers::pi * (i == nlon ? 0 : i) / nlon;
      glm::dvec3 n(st * std::sin(phi), ct, st * std::cos(phi));
      m.normals.push_back(n);
      m.positions.push_back(s.center + s.radius * n);
      m.uvs.push_back({s.uv_repeat.x * double(i) / nlon, s.uv_repeat.y * double(j) / nlat});
    }
  }
  for (int j = 0; j < nlat; ++j) {
    for (int i = 0; i < nlon; ++i) {
      uint32_t a = idx(i, j), b = idx(i + 1, j), c = idx(i + 1, j + 1), d = idx(i, j + 1);
      if (j != 0) m.triangles.push_back({a, d, b});          // skip the pole's sliver
      if (j != nlat - 1) m.triangles.push_back({b, d, c});
    }
  }
  return m;
}

TriangleMesh tessellatePlane(const Plane& p) {
  glm::dvec3 n = glm::normalize(p.normal);
  glm::dvec3 hint = std::abs(n.y) > 0.999999 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
  glm::dvec3 u_axis = glm::normalize(glm::cross(hint, n));
  glm::dvec3 up = glm::cross(n, u_axis);  // v runs opposite to this
  TriangleMesh m;
  for (int t = 0; t <= 1; ++t) {
    for (int s = 0; s <= 1; ++s) {
      m.positions.push_back(p.center + (s - 0.5) * p.size.x * u_axis - (t - 0.5) * p.size.y * up);
      m.normals.push_back(n);
      m.uvs.push_back({s * p.uv_repeat.x, t * p.uv_repeat.y});
    }
  }
  // 0 = top-left, 1 = top-right, 2 = bottom-left, 3 = bottom-right (seen
  // from the front): counter-clockwise seen from +n.
  m.triangles = {{0, 2, 3}, {0, 3, 1}};
  return m;
}

// Rounds every attribute to the nearest float32. glTF buffers and POV-Ray's
// mesh2 store float32; rounding here makes the reference renderer trace
// exactly the triangles the other renderers receive (float_rounding.h: a
// plain double(float(x)) is dropped by the optimiser).
void roundToFloat(TriangleMesh& m) {
  for (auto& p : m.positions) p = roundedToFloat(p);
  for (auto& n : m.normals) n = roundedToFloat(n);
  for (auto& uv : m.uvs) uv = roundedToFloat(uv);
}

TriangleMesh tessellateExact(const Shape& shape) {
  return std::visit(
      [](const auto& s) -> TriangleMesh {
        using S = std::decay_t<decltype(s)>;
        if constexpr (std::is_same_v<S, TorusKnot>) return tessellateTorusKnot(s);
        else if constexpr (std::is_same_v<S, UvSphere>) return tessellateSphere(s);
        else if constexpr (std::is_same_v<S, Plane>) return tessellatePlane(s);
        else throw std::invalid_argument("tessellate: a model file has one mesh per primitive (scene_meshes.h)");
      },
      shape);
}

TriangleMesh tessellate(const Shape& shape) {
  TriangleMesh m = tessellateExact(shape);
  roundToFloat(m);
  return m;
}

}  // namespace xval
