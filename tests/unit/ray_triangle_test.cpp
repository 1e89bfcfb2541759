// The double-precision watertight ray/triangle test.
#include <gtest/gtest.h>

#include <random>

#include "render/ray_triangle.h"

using namespace xval;
using glm::dvec3;

TEST(RayTriangle, HitDistanceAndBarycentrics) {
  RayShear r(dvec3(0.2, 0.3, 5), dvec3(0, 0, -1));
  TriangleHit h;
  ASSERT_TRUE(intersectTriangle(r, dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), 0, 1e30, h));
  EXPECT_DOUBLE_EQ(h.t, 5.0);
  EXPECT_NEAR(h.b1, 0.2, 1e-15);
  EXPECT_NEAR(h.b2, 0.3, 1e-15);
  // Two-sided: from behind too.
  RayShear back(dvec3(0.2, 0.3, -5), dvec3(0, 0, 1));
  EXPECT_TRUE(intersectTriangle(back, dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), 0, 1e30, h));
  // Outside, and beyond t_max.
  RayShear miss(dvec3(0.8, 0.8, 5), dvec3(0, 0, -1));
  EXPECT_FALSE(intersectTriangle(miss, dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), 0, 1e30, h));
  EXPECT_FALSE(intersectTriangle(r, dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), 0, 4.0, h));
}

TEST(RayTriangle, ZeroAreaTriangleNeverHits) {
  RayShear r(dvec3(0.5, 0, 5), dvec3(0, 0, -1));
  TriangleHit h;
  EXPECT_FALSE(intersectTriangle(r, dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(2, 0, 0), 0, 1e30, h));
}

// Rays aimed exactly at a shared edge hit at least one of its triangles.
TEST(RayTriangle, WatertightOnSharedEdges) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int misses = 0;
  for (int i = 0; i < 20000; ++i) {
    dvec3 a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    dvec3 c = dvec3(u(rng), u(rng), u(rng)) + dvec3(0, 0, 3);
    dvec3 d = a + b - c;  // a parallelogram: d is on the other side of ab
    double s = (u(rng) + 1) / 2;
    dvec3 on_edge = a + s * (b - a);
    dvec3 o(u(rng) * 3, u(rng) * 3, 10);
    RayShear r(o, glm::normalize(on_edge - o));
    TriangleHit h;
    bool h1 = intersectTriangle(r, a, b, c, 0, 1e30, h);
    bool h2 = intersectTriangle(r, b, a, d, 0, 1e30, h);
    if (!h1 && !h2) ++misses;
  }
  EXPECT_EQ(misses, 0);
}
