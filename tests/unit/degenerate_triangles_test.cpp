// The degenerate-triangle rule (geometry/degenerate_triangles.h): which
// triangles are dropped, which twin is kept, and that zero-area triangles
// with distinct indices stay (Blender keeps them too).
#include <gtest/gtest.h>

#include "geometry/degenerate_triangles.h"

namespace xval {
namespace {

using T = glm::u32vec3;

TEST(DegenerateTriangles, RepeatedIndexInAnyPositionIsDropped) {
  const DroppedTriangles d = dropDegenerateTriangles({T(0, 1, 2), T(3, 3, 4), T(3, 4, 3), T(4, 3, 3), T(5, 5, 5)});
  EXPECT_EQ(d.repeated_index, 4u);
  EXPECT_EQ(d.duplicates, 0u);
  ASSERT_EQ(d.kept.size(), 1u);
  EXPECT_EQ(d.kept[0], T(0, 1, 2));
}

TEST(DegenerateTriangles, TwinsOfEitherWindingKeepTheFirst) {
  // (2, 1, 0) first, then its rotation, its reverse and its own repeat,
  // spread among other triangles: only the first of the four stays.
  // Blender 3.4.1's mesh validation, given this very list, keeps the same
  // three (measured with a hand-made mesh and Mesh.validate()).
  const DroppedTriangles d = dropDegenerateTriangles(
      {T(5, 6, 7), T(2, 1, 0), T(1, 2, 3), T(1, 0, 2), T(0, 1, 2), T(2, 1, 0), T(3, 2, 1)});
  EXPECT_EQ(d.repeated_index, 0u);
  EXPECT_EQ(d.duplicates, 4u);  // three twins of (2, 1, 0), one of (1, 2, 3)
  const std::vector<T> want{T(5, 6, 7), T(2, 1, 0), T(1, 2, 3)};
  EXPECT_EQ(d.kept, want);
}

TEST(DegenerateTriangles, DistinctIndicesStayEvenWithZeroArea) {
  // The rule looks at indices only: triangles on coincident or collinear
  // positions with three different indices are kept (as Blender keeps them).
  const std::vector<T> tris{T(0, 1, 2), T(0, 1, 3), T(0, 3, 1), T(4, 5, 6)};
  const DroppedTriangles d = dropDegenerateTriangles(tris);
  EXPECT_EQ(d.dropped(), 1u);  // (0, 3, 1) is (0, 1, 3) reversed
  EXPECT_EQ(d.kept, (std::vector<T>{T(0, 1, 2), T(0, 1, 3), T(4, 5, 6)}));
  EXPECT_TRUE(dropDegenerateTriangles({}).kept.empty());
}

}  // namespace
}  // namespace xval
