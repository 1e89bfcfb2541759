// The rasteriser's projection and binning (render/raster.h) give the same
// bins, in the same order, and the same first hits on any number of
// threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "geometry/mesh.h"
#include "render/raster.h"

using namespace xval;

namespace {

// Every field of every sample's hit, band by band, at two sample offsets.
std::vector<Hit> allHits(const Rasteriser& r, int width, int band_rows) {
  std::vector<Hit> all, band(size_t(band_rows) * width);
  for (int b = 0; b < r.bands(); ++b)
    for (double o : {0.5, 0.125}) {
      std::fill(band.begin(), band.end(), Hit{});
      r.visibility(b, o, o, true, band);
      all.insert(all.end(), band.begin(), band.end());
    }
  return all;
}

}  // namespace

TEST(Raster, ProjectionAndBinningAreTheSameOnAnyThreadCount) {
  // Three meshes of several binning chunks (2^16 triangles) each; the
  // second with its back faces skipped.
  std::vector<TriangleMesh> meshes;
  for (int k = 0; k < 3; ++k) {
    TorusKnot knot;
    knot.segments_along = 2000 + 500 * k, knot.segments_around = 40;
    knot.center = glm::dvec3(0.4 * k - 0.4, 0.1 * k, -0.3 * k);
    meshes.push_back(tessellate(knot));
  }
  ASSERT_GT(meshes[0].triangles.size(), size_t(2) << 16);
  Camera c;
  c.width = 160, c.height = 120;
  const CameraRays cam(c);
  const std::vector<bool> cull = {false, true, false};
  const Rasteriser one(meshes, cam, 16, cull, 1);
  const std::vector<Hit> hits_one = allHits(one, c.width, 16);
  size_t binned = 0;
  for (int b = 0; b < one.bands(); ++b) {
    binned += one.bin(b).size();
    // As the serial loop bins them: ascending (mesh, triangle).
    EXPECT_TRUE(std::is_sorted(one.bin(b).begin(), one.bin(b).end())) << "band " << b;
  }
  EXPECT_GT(binned, meshes[0].triangles.size());
  EXPECT_GT(one.culledTriangles(), 0u);
  for (int threads : {2, 3, 8}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    const Rasteriser many(meshes, cam, 16, cull, threads);
    ASSERT_EQ(many.bands(), one.bands());
    EXPECT_EQ(many.culledTriangles(), one.culledTriangles());
    for (int b = 0; b < one.bands(); ++b) EXPECT_EQ(many.bin(b), one.bin(b)) << "band " << b;
    const std::vector<Hit> hits = allHits(many, c.width, 16);
    ASSERT_EQ(hits.size(), hits_one.size());
    size_t differ = 0;
    for (size_t i = 0; i < hits.size(); ++i) {
      const Hit &a = hits[i], &b = hits_one[i];
      // Bit for bit (memcmp of the doubles: -0 and NaN would count).
      differ += a.hit != b.hit || a.mesh != b.mesh || a.triangle != b.triangle ||
                std::memcmp(&a.t, &b.t, sizeof a.t) || std::memcmp(&a.b1, &b.b1, sizeof a.b1) ||
                std::memcmp(&a.b2, &b.b2, sizeof a.b2);
    }
    EXPECT_EQ(differ, 0u);
  }
}
