#include "render/raster.h"

#include "render/pixel_index.h"
#include "render/raster_band.h"

#include <algorithm>
#include <cmath>

namespace xval {

bool Rasteriser::applicable(const std::vector<TriangleMesh>& meshes, const CameraRays& cam) {
  for (const auto& m : meshes)
    for (const auto& p : m.positions)
      if (!(glm::dot(p - cam.origin, cam.forward) > 0.0)) return false;
  return true;
}

Rasteriser::Rasteriser(const std::vector<TriangleMesh>& meshes, const CameraRays& cam, int band_rows,
                       const std::vector<bool>& cull_back)
    : meshes_(&meshes), cam_(&cam), band_rows_(band_rows) {
  const double sx = cam.tan_half_fov * cam.aspect, sy = cam.tan_half_fov;
  const double hw = 0.5 * cam.width, hh = 0.5 * cam.height;
  projected_.resize(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m) {
    auto& out = projected_[m];
    out.resize(meshes[m].positions.size());
    for (size_t i = 0; i < out.size(); ++i) {
      const glm::dvec3 d = meshes[m].positions[i] - cam.origin;
      const double z = glm::dot(d, cam.forward);
      out[i] = {(glm::dot(d, cam.right) / (z * sx) + 1.0) * hw, (1.0 - glm::dot(d, cam.up) / (z * sy)) * hh,
                1.0 / z};
    }
  }
  const int nb = (cam.height + band_rows - 1) / band_rows;
  bins_.assign(nb, {});
  for (size_t m = 0; m < meshes.size(); ++m) {
    const auto& P = projected_[m];
    const auto& tris = meshes[m].triangles;
    const bool cull = m < cull_back.size() && cull_back[m];
    for (size_t t = 0; t < tris.size(); ++t) {
      if (cull) {
        const Vertex &a = P[tris[t][0]], &b = P[tris[t][1]], &c = P[tris[t][2]];
        if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) > 0.0) {  // a back face
          ++culled_;
          continue;
        }
      }
      const double y0 = std::min({P[tris[t][0]].y, P[tris[t][1]].y, P[tris[t][2]].y});
      const double y1 = std::max({P[tris[t][0]].y, P[tris[t][1]].y, P[tris[t][2]].y});
      // Samples sit at j + oy, oy in [0, 1): rows floor(y0) - 1 .. floor(y1).
      const int j0 = clampedIndex(std::floor(y0) - 1.0, 0, cam.height);
      const int j1 = clampedIndex(std::floor(y1), -1, cam.height - 1);
      if (!(j0 <= j1)) continue;  // off screen (or NaN)
      for (int b = j0 / band_rows; b <= j1 / band_rows; ++b)
        bins_[b].push_back((std::uint64_t(m) << 32) | std::uint64_t(t));
    }
  }
}

void Rasteriser::visibility(int band, double ox, double oy, bool want_t, std::vector<Hit>& out) const {
  const int W = cam_->width, H = cam_->height;
  const int row0 = band * band_rows_, row1 = std::min(H, row0 + band_rows_);
  const size_t n = size_t(row1 - row0) * W;
  thread_local std::vector<double> best;  // largest 1/z so far per sample; 0 = nothing
  best.assign(n + kRasterPad, 0.0);
  rasterBand({meshes_, &projected_, &bins_[band], cam_, row0, row1, ox, oy, want_t, out.data(), best.data()});
  for (size_t k = 0; k < n; ++k) out[k].hit = best[k] > 0.0;
}

}  // namespace xval
