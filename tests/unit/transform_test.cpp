// Object transforms (geometry/transform.h): normals by the inverse
// transpose against the analytic ellipsoid normal, winding under a mirror,
// the order scale -> rotate -> translate, and the refusals.
#include <gtest/gtest.h>

#include <cmath>

#include "geometry/mesh.h"
#include "geometry/transform.h"

namespace xval {
namespace {

UvSphere unitSphere() {
  UvSphere s;
  s.center = glm::dvec3(0.0);
  s.radius = 1.0;
  s.segments_longitude = 48;
  s.segments_latitude = 24;
  return s;
}

TEST(Transform, EllipsoidNormalsAreTheInverseTransposeOfTheSphere) {
  // x = R S p + t on the unit sphere |p| = 1 is the ellipsoid
  // f(x) = |S^-1 R^T (x - t)|^2 = 1, whose outward normal is
  // grad f ~ R S^-2 R^T (x - t).
  ObjectTransform t;
  t.scale = {2.0, 0.5, 1.5};
  t.rotate = {{1.0, 1.0, 0.0}, 30.0};
  t.translate = {1.0, -2.0, 3.0};
  const Affine f = toAffine(t);
  const glm::dmat3 r = rotationMatrix(t.rotate);
  glm::dmat3 s_inv2(0.0);
  for (int i = 0; i < 3; ++i) s_inv2[i][i] = 1.0 / (t.scale[i] * t.scale[i]);
  const TriangleMesh sphere = tessellateSphere(unitSphere());
  const TriangleMesh e = transformed(sphere, f);
  ASSERT_EQ(e.normals.size(), sphere.normals.size());
  double worst = 0.0;
  for (size_t i = 0; i < e.positions.size(); ++i) {
    const glm::dvec3 x = e.positions[i];
    const glm::dvec3 p = glm::inverse(f.linear) * (x - t.translate);  // back on the sphere
    ASSERT_NEAR(glm::length(p), 1.0, 1e-12) << "vertex " << i;
    const glm::dvec3 expected = glm::normalize(r * s_inv2 * glm::transpose(r) * (x - t.translate));
    worst = std::max(worst, glm::length(e.normals[i] - expected));
  }
  EXPECT_LT(worst, 1e-12);
}

// g . (n0 + n1 + n2) > 0 and g . (centroid - centre) > 0 for every triangle:
// counter-clockwise seen from outside, normals outward.
void expectOutwardWinding(const TriangleMesh& m, glm::dvec3 centre) {
  size_t bad = 0;
  for (const auto& t : m.triangles) {
    const glm::dvec3 a = m.positions[t.x], b = m.positions[t.y], c = m.positions[t.z];
    const glm::dvec3 g = glm::cross(b - a, c - a);
    if (glm::length(g) == 0.0) continue;
    if (glm::dot(g, m.normals[t.x] + m.normals[t.y] + m.normals[t.z]) <= 0.0 ||
        glm::dot(g, (a + b + c) / 3.0 - centre) <= 0.0)
      ++bad;
  }
  EXPECT_EQ(bad, 0u) << "of " << m.triangles.size() << " triangles";
}

TEST(Transform, MirroringKeepsOutwardWinding) {
  const TriangleMesh sphere = tessellateSphere(unitSphere());
  expectOutwardWinding(sphere, glm::dvec3(0.0));
  for (glm::dvec3 scale : {glm::dvec3(-1, 1, 1), glm::dvec3(2, -0.5, 1), glm::dvec3(-1, -1, -3)}) {
    ObjectTransform t;
    t.scale = scale;
    t.translate = {0.5, 0.0, -1.0};
    const Affine f = toAffine(t);
    EXPECT_EQ(f.mirrors(), scale.x * scale.y * scale.z < 0);
    SCOPED_TRACE("scale " + std::to_string(scale.x) + " " + std::to_string(scale.y) + " " + std::to_string(scale.z));
    expectOutwardWinding(transformed(sphere, f), t.translate);
  }
}

TEST(Transform, ScaleThenRotateThenTranslate) {
  ObjectTransform t;
  t.scale = {2.0, 3.0, 1.0};
  t.rotate = {{0.0, 0.0, 5.0}, 90.0};  // the axis need not be unit length
  t.translate = {1.0, 0.0, 0.0};
  const Affine f = toAffine(t);
  // (1, 1, 0) -> scale (2, 3, 0) -> +90 deg about z (-3, 2, 0) -> (-2, 2, 0).
  const glm::dvec3 q = f.point({1.0, 1.0, 0.0});
  EXPECT_NEAR(q.x, -2.0, 1e-15);
  EXPECT_NEAR(q.y, 2.0, 1e-15);
  EXPECT_NEAR(q.z, 0.0, 1e-15);
  // then(first, second) applies first, then second.
  Affine g;
  g.linear = glm::dmat3(0, 0, 1, 1, 0, 0, 0, 1, 0);  // a cyclic permutation
  g.offset = {0.0, 5.0, 0.0};
  const glm::dvec3 p{0.3, -1.2, 2.5};
  const glm::dvec3 want = g.point(f.point(p)), got = then(f, g).point(p);
  EXPECT_NEAR(glm::length(want - got), 0.0, 1e-14);
  EXPECT_GT(glm::length(then(g, f).point(p) - got), 0.1);  // the order matters
}

TEST(Transform, RefusesSingularAndNonFinite) {
  ObjectTransform t;
  t.scale = {1.0, 0.0, 1.0};
  try {
    toAffine(t);
    FAIL() << "a zero scale was accepted";
  } catch (const TransformError& e) {
    EXPECT_NE(std::string(e.what()).find("scale[1]"), std::string::npos) << e.what();
  }
  ObjectTransform r;
  r.rotate.axis = glm::dvec3(0.0);
  EXPECT_THROW(toAffine(r), TransformError);
  r.rotate = {{0, 1, 0}, NAN};
  EXPECT_THROW(toAffine(r), TransformError);
  Affine flat;
  flat.linear[2] = glm::dvec3(0.0);
  EXPECT_THROW(transformed(tessellateSphere(unitSphere()), flat), TransformError);
}

}  // namespace
}  // namespace xval
