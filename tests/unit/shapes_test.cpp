// Sphere and plane meshes.
#include <gtest/gtest.h>

#include "geometry/mesh.h"

using namespace xval;

namespace {
int inwardTriangles(const TriangleMesh& m) {
  int inward = 0;
  for (const auto& t : m.triangles) {
    glm::dvec3 g = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                              m.positions[t[2]] - m.positions[t[0]]);
    if (glm::dot(g, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]) <= 0) ++inward;
  }
  return inward;
}
}  // namespace

TEST(Shapes, SphereVerticesOnSphereWithRadialNormals) {
  UvSphere s;
  s.center = {1, 2, 3};
  s.radius = 2.0;
  TriangleMesh m = tessellateSphere(s);
  EXPECT_EQ(m.vertexCount(), size_t(s.segments_longitude + 1) * (s.segments_latitude + 1));
  EXPECT_EQ(m.triangleCount(), size_t(s.segments_longitude) * (2 * s.segments_latitude - 2));
  for (size_t i = 0; i < m.vertexCount(); ++i) {
    EXPECT_NEAR(glm::length(m.positions[i] - s.center), 2.0, 1e-14);
    EXPECT_LT(glm::length(m.normals[i] - (m.positions[i] - s.center) / 2.0), 1e-14);
  }
  EXPECT_EQ(inwardTriangles(m), 0);
}

TEST(Shapes, PlaneFacesItsNormalAndVRunsDown) {
  Plane p;
  TriangleMesh m = tessellatePlane(p);
  EXPECT_EQ(inwardTriangles(m), 0);
  // Vertex 0 is top-left seen from the front (+z): uv (0, 0).
  EXPECT_LT(m.positions[0].x, 0);
  EXPECT_GT(m.positions[0].y, 0);
  EXPECT_EQ(m.uvs[0], glm::dvec2(0, 0));
  EXPECT_EQ(m.uvs[3], glm::dvec2(1, 1));
  Plane up;
  up.normal = {0, 1, 0};
  EXPECT_EQ(inwardTriangles(tessellatePlane(up)), 0);
}
