#include "render/raster.h"

#include "process/job_pool.h"
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

// Projection and binning on `threads` threads, bit for bit as on one:
// each vertex is projected by the same operations wherever it runs, and
// the triangles are cut into contiguous chunks binned apart, each band's
// bin then the chunks' lists in chunk order, so every bin holds its
// triangles in ascending (mesh, triangle) order, as the serial loop put
// them (the order decides ties of 1/z: the first binned wins).
Rasteriser::Rasteriser(const std::vector<TriangleMesh>& meshes, const CameraRays& cam, int band_rows,
                       const std::vector<bool>& cull_back, int threads)
    : meshes_(&meshes), cam_(&cam), band_rows_(band_rows) {
  const double sx = cam.tan_half_fov * cam.aspect, sy = cam.tan_half_fov;
  const double hw = 0.5 * cam.width, hh = 0.5 * cam.height;
  // Jobs of about kChunk vertices or triangles: (mesh, first, last).
  constexpr size_t kChunk = 1 << 13;
  struct Range {
    size_t mesh, begin, end;
  };
  auto chunks = [&](auto count) {
    std::vector<Range> r;
    for (size_t m = 0; m < meshes.size(); ++m)
      for (size_t i = 0; i < count(meshes[m]); i += kChunk) r.push_back({m, i, std::min(count(meshes[m]), i + kChunk)});
    return r;
  };
  const int workers = std::max(1, threads);
  projected_.resize(meshes.size());
  for (size_t m = 0; m < meshes.size(); ++m) projected_[m].resize(meshes[m].positions.size());
  const std::vector<Range> vertex_jobs = chunks([](const TriangleMesh& m) { return m.positions.size(); });
  runJobPool(vertex_jobs.size(), workers, [&](size_t job) {
    const Range& r = vertex_jobs[job];
    const auto& pos = meshes[r.mesh].positions;
    auto& out = projected_[r.mesh];
    for (size_t i = r.begin; i < r.end; ++i) {
      const glm::dvec3 d = pos[i] - cam.origin;
      const double z = glm::dot(d, cam.forward);
      out[i] = {(glm::dot(d, cam.right) / (z * sx) + 1.0) * hw, (1.0 - glm::dot(d, cam.up) / (z * sy)) * hh,
                1.0 / z};
    }
  });
  const int nb = (cam.height + band_rows - 1) / band_rows;
  const std::vector<Range> triangle_jobs = chunks([](const TriangleMesh& m) { return m.triangles.size(); });
  std::vector<std::vector<std::vector<std::uint64_t>>> chunk_bins(triangle_jobs.size());
  std::vector<size_t> chunk_culled(triangle_jobs.size(), 0);
  runJobPool(triangle_jobs.size(), workers, [&](size_t job) {
    const Range& r = triangle_jobs[job];
    const auto& P = projected_[r.mesh];
    const auto& tris = meshes[r.mesh].triangles;
    const bool cull = r.mesh < cull_back.size() && cull_back[r.mesh];
    auto& bins = chunk_bins[job];
    bins.assign(nb, {});
    for (size_t t = r.begin; t < r.end; ++t) {
      if (cull) {
        const Vertex &a = P[tris[t][0]], &b = P[tris[t][1]], &c = P[tris[t][2]];
        if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) > 0.0) {  // a back face
          ++chunk_culled[job];
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
        bins[b].push_back((std::uint64_t(r.mesh) << 32) | std::uint64_t(t));
    }
  });
  for (size_t c : chunk_culled) culled_ += c;
  bins_.assign(nb, {});
  runJobPool(size_t(nb), workers, [&](size_t b) {
    size_t total = 0;
    for (const auto& cb : chunk_bins) total += cb[b].size();
    bins_[b].reserve(total);
    for (const auto& cb : chunk_bins) bins_[b].insert(bins_[b].end(), cb[b].begin(), cb[b].end());
  });
}

void Rasteriser::visibility(int band, double ox, double oy, bool want_t, BandHits& out) const {
  const int W = cam_->width, H = cam_->height;
  const int row0 = band * band_rows_, row1 = std::min(H, row0 + band_rows_);
  const size_t n = size_t(row1 - row0 + 1) * W + kRasterPad;  // raster_band.h
  out.best.assign(n, 0.0);  // only best is read before it is written
  for (auto* v : {&out.b1, &out.b2}) v->resize(n);
  out.key.resize(n);
  out.t.resize(want_t ? n : 0);
  rasterBand({meshes_, &projected_, &bins_[band], cam_, row0, row1, ox, oy, out.best.data(), out.key.data(),
              out.b1.data(), out.b2.data(), want_t ? out.t.data() : nullptr});
}

void Rasteriser::visibility(int band, double ox, double oy, bool want_t, std::vector<Hit>& out) const {
  thread_local BandHits soa;
  visibility(band, ox, oy, want_t, soa);
  const int W = cam_->width, H = cam_->height;
  const int row0 = band * band_rows_, row1 = std::min(H, row0 + band_rows_);
  for (size_t k = 0; k < size_t(row1 - row0) * W; ++k) {
    Hit& h = out[k];
    h.hit = soa.hit(k);
    if (!h.hit) continue;
    h.mesh = std::uint32_t(soa.key[k] >> 32), h.triangle = std::uint32_t(soa.key[k]);
    h.b1 = soa.b1[k], h.b2 = soa.b2[k];
    if (want_t) h.t = soa.t[k];
  }
}

}  // namespace xval
