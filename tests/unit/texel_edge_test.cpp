// texelEdgeRoundings (texture/texel_edge.h): the distance of a uv from the
// nearest texel edge of a nearest-filtered texture, in float32 roundings
// of the triangle's uvs.
#include <gtest/gtest.h>

#include <cmath>

#include "texture/texel_edge.h"

namespace xval {
namespace {

const glm::dvec2 kUnitCorners[3] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};  // largest |u| = |v| = 1

TEST(TexelEdge, DistanceInRoundingsOfTheLargestCornerUv) {
  const double s = std::ldexp(1.0, -24);  // one rounding of uvs of size 1
  // An 8-texel texture: edges at k / 8. u = 3/8 + 5 s is 5 roundings from
  // an edge; v in the middle of a texel is far.
  EXPECT_NEAR(texelEdgeRoundings(glm::dvec2(3.0 / 8 + 5 * s, 0.5 / 8), kUnitCorners, 8, 8), 5.0, 1e-6);
  // Below the edge counts the same; the nearer axis counts.
  EXPECT_NEAR(texelEdgeRoundings(glm::dvec2(3.0 / 8 - 5 * s, 2.0 / 8 + 2 * s), kUnitCorners, 8, 8), 2.0, 1e-6);
  // The wrap: whole u are edges too (u = 2 + 3 s, corners up to 2: s doubles).
  const glm::dvec2 far_corners[3] = {{2.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}};
  EXPECT_NEAR(texelEdgeRoundings(glm::dvec2(2.0 + 6 * s, 0.5 / 8), far_corners, 8, 8), 3.0, 1e-6);
  // A texel centre: half a texel, 2^24 / 16 roundings.
  EXPECT_NEAR(texelEdgeRoundings(glm::dvec2(0.5 / 8, 0.5 / 8), kUnitCorners, 8, 8), std::ldexp(1.0, 24) / 16, 1e-3);
}

TEST(TexelEdge, AllZeroUvsAndNonFiniteUvsAreFar) {
  const glm::dvec2 zero[3] = {{0.0, 0.0}, {0.0, 0.0}, {0.0, 0.0}};
  EXPECT_EQ(texelEdgeRoundings(glm::dvec2(0.0, 0.0), zero, 8, 8), double(kFarFromTexelEdge));
  EXPECT_EQ(texelEdgeRoundings(glm::dvec2(NAN, INFINITY), kUnitCorners, 8, 8), double(kFarFromTexelEdge));
}

}  // namespace
}  // namespace xval
