// The torus knot mesh: the paper's tessellation, normals, frame, seams, uvs.
#include <gtest/gtest.h>

#include <numbers>

#include "geometry/mesh.h"
#include "geometry/torus_knot.h"

using namespace xval;

namespace {
constexpr double kTwoPi = 2.0 * std::numbers::pi;
}

TEST(TorusKnot, PaperTessellationHas61440TrianglesAnd31529Vertices) {
  TriangleMesh m = tessellateTorusKnot(TorusKnot{});
  EXPECT_EQ(m.triangleCount(), 61440u);
  EXPECT_EQ(m.vertexCount(), 31529u);  // 769 x 41, seams duplicated
  EXPECT_EQ(m.normals.size(), m.vertexCount());
  EXPECT_EQ(m.uvs.size(), m.vertexCount());
}

TEST(TorusKnot, CentreLineIsTheTorusKnot) {
  TorusKnot k;
  k.p = 3, k.q = 5;
  TorusKnotCurve c(k);
  for (double t : {0.0, 0.3, 1.7, 4.0}) {
    glm::dvec3 p = c.point(t);
    // On the torus: (sqrt(x^2 + y^2) - R)^2 + z^2 = r^2.
    double ring = std::sqrt(p.x * p.x + p.y * p.y) - k.major_radius;
    EXPECT_NEAR(ring * ring + p.z * p.z, k.minor_radius * k.minor_radius, 1e-12);
    // The derivative matches a central difference.
    glm::dvec3 fd = (c.point(t + 1e-6) - c.point(t - 1e-6)) / 2e-6;
    EXPECT_LT(glm::length(fd - c.derivative(t)), 1e-6);
  }
}

TEST(TorusKnot, NormalsAreUnitAndOrthogonalToTheCurveTangent) {
  TorusKnot k;
  TriangleMesh m = tessellateTorusKnot(k);
  TorusKnotCurve c(k);
  const int nr = k.segments_around + 1;
  double worst_len = 0, worst_dot = 0, worst_radius = 0;
  for (int i = 0; i <= k.segments_along; ++i) {
    double t = kTwoPi * (i % k.segments_along) / k.segments_along;
    glm::dvec3 tangent = glm::normalize(c.derivative(t));
    for (int j = 0; j < nr; ++j) {
      const glm::dvec3& n = m.normals[i * nr + j];
      worst_len = std::max(worst_len, std::abs(glm::length(n) - 1.0));
      worst_dot = std::max(worst_dot, std::abs(glm::dot(n, tangent)));
      // The normal is the exact radial direction of the tube.
      worst_radius = std::max(worst_radius,
                              glm::length(m.positions[i * nr + j] - (c.point(t) + k.tube_radius * n)));
    }
  }
  EXPECT_LT(worst_len, 1e-14);
  EXPECT_LT(worst_dot, 1e-13);
  EXPECT_LT(worst_radius, 1e-14);
}

// No twist jump: consecutive frames turn by a small, even amount, and the
// frame at t = 2 pi equals the frame at t = 0.
TEST(TorusKnot, FrameIsSmoothAndClosed) {
  TorusKnot k;
  TorusKnotCurve c(k);
  CurveFrame f0 = c.frame(0.0), f1 = c.frame(kTwoPi);
  EXPECT_LT(glm::length(f0.normal - f1.normal), 1e-9);
  EXPECT_LT(glm::length(f0.binormal - f1.binormal), 1e-9);
  double worst_step = 0;
  const int steps = 4096;
  for (int i = 0; i < steps; ++i) {
    CurveFrame a = c.frame(kTwoPi * i / steps), b = c.frame(kTwoPi * (i + 1) / steps);
    worst_step = std::max(worst_step, std::acos(std::min(1.0, glm::dot(a.normal, b.normal))));
  }
  // The curve's tangent turns at most ~0.02 rad per step here; a twist
  // jump would show as a step of order 1.
  EXPECT_LT(worst_step, 0.02);
}

TEST(TorusKnot, FrameDoesNotDependOnTessellation) {
  TorusKnot a, b;
  b.segments_along = 96;
  b.segments_around = 12;
  TriangleMesh ma = tessellateTorusKnot(a), mb = tessellateTorusKnot(b);
  // Vertex (i, j) of b is vertex (8 i, (40/12) j) of a where both exist:
  // check every 3rd around of b against a (j = 0 and ring starts).
  for (int i = 0; i <= 96; ++i)
    EXPECT_LT(glm::length(mb.positions[i * 13] - ma.positions[(8 * i) * 41]), 1e-12) << i;
}

TEST(TorusKnot, SeamsDuplicateVerticesAndUvsAreContinuous) {
  TorusKnot k;
  TriangleMesh m = tessellateTorusKnot(k);
  const int na = k.segments_along, nr = k.segments_around;
  auto at = [nr](int i, int j) { return i * (nr + 1) + j; };
  for (int j = 0; j <= nr; ++j) {
    EXPECT_EQ(m.positions[at(na, j)], m.positions[at(0, j)]);
    EXPECT_EQ(m.normals[at(na, j)], m.normals[at(0, j)]);
    EXPECT_DOUBLE_EQ(m.uvs[at(na, j)].x, k.uv_repeat.x);
  }
  for (int i = 0; i <= na; ++i) {
    EXPECT_EQ(m.positions[at(i, nr)], m.positions[at(i, 0)]);
    EXPECT_DOUBLE_EQ(m.uvs[at(i, nr)].y, k.uv_repeat.y);
  }
  // Within every triangle uv changes by at most one step: no triangle
  // spans the seam (which would smear the whole texture across it).
  double du = k.uv_repeat.x / na, dv = k.uv_repeat.y / nr;
  for (const auto& t : m.triangles) {
    for (int e = 0; e < 3; ++e) {
      glm::dvec2 d = glm::abs(m.uvs[t[e]] - m.uvs[t[(e + 1) % 3]]);
      EXPECT_LE(d.x, du * (1 + 1e-9));
      EXPECT_LE(d.y, dv * (1 + 1e-9));
    }
  }
}

TEST(TorusKnot, TrianglesFaceOutward) {
  TriangleMesh m = tessellateTorusKnot(TorusKnot{});
  int inward = 0;
  for (const auto& t : m.triangles) {
    glm::dvec3 g = glm::cross(m.positions[t[1]] - m.positions[t[0]],
                              m.positions[t[2]] - m.positions[t[0]]);
    if (glm::dot(g, m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]]) <= 0) ++inward;
  }
  EXPECT_EQ(inward, 0);
}
