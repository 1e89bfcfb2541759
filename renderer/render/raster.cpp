#include "render/raster.h"

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
      const int j0 = std::max(0, int(std::floor(y0)) - 1);
      const int j1 = std::min(cam.height - 1, int(std::floor(y1)));
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
  best.assign(n, 0.0);
  // The bounding box only has to contain every sample the exact edge test
  // accepts; the 1e-7 px slack covers the rounding of minx - ox.
  constexpr double kSlack = 1e-7;

  for (std::uint64_t key : bins_[band]) {
    const uint32_t m = uint32_t(key >> 32), t = uint32_t(key);
    const glm::u32vec3 tri = (*meshes_)[m].triangles[t];
    const Vertex* P = projected_[m].data();
    const Vertex v[3] = {P[tri[0]], P[tri[1]], P[tri[2]]};
    const double minx = std::min({v[0].x, v[1].x, v[2].x}), maxx = std::max({v[0].x, v[1].x, v[2].x});
    const double miny = std::min({v[0].y, v[1].y, v[2].y}), maxy = std::max({v[0].y, v[1].y, v[2].y});
    const int i0 = std::max(0, int(std::ceil(minx - ox - kSlack)));
    const int i1 = std::min(W - 1, int(std::floor(maxx - ox + kSlack)));
    const int j0 = std::max(row0, int(std::ceil(miny - oy - kSlack)));
    const int j1 = std::min(row1 - 1, int(std::floor(maxy - oy + kSlack)));
    if (i0 > i1 || j0 > j1) continue;  // no sample inside the box (or NaN)
    const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    if (!(area != 0.0)) continue;  // edge-on (or NaN): no sample sees it
    const double s = area > 0.0 ? 1.0 : -1.0;
    // Edge k is opposite vertex k: from u = vertex k+1 to w = vertex k+2,
    // evaluated from the lower vertex index (lo) towards the higher (hi):
    //   C_k(p) = ex (p.y - lo.y) - ey (p.x - lo.x),  e_k = sign_k C_k.
    double lx[3], ly[3], ex[3], ey[3], sign[3];
    for (int k = 0; k < 3; ++k) {
      const int u = (k + 1) % 3, w = (k + 2) % 3;
      const bool forward = tri[u] < tri[w];
      const Vertex& lo = forward ? v[u] : v[w];
      const Vertex& hi = forward ? v[w] : v[u];
      lx[k] = lo.x, ly[k] = lo.y, ex[k] = hi.x - lo.x, ey[k] = hi.y - lo.y;
      sign[k] = forward ? s : -s;
    }
    for (int j = j0; j <= j1; ++j) {
      const double py = j + oy;
      const double r0 = ex[0] * (py - ly[0]), r1 = ex[1] * (py - ly[1]), r2 = ex[2] * (py - ly[2]);
      double* best_row = &best[size_t(j - row0) * W];
      Hit* out_row = &out[size_t(j - row0) * W];
      for (int i = i0; i <= i1; ++i) {
        const double px = i + ox;
        const double e0 = sign[0] * (r0 - ey[0] * (px - lx[0]));
        const double e1 = sign[1] * (r1 - ey[1] * (px - lx[1]));
        const double e2 = sign[2] * (r2 - ey[2] * (px - lx[2]));
        // On an edge: only the triangle that runs it from its lower index.
        const bool inside = (e0 > 0.0 || (e0 == 0.0 && sign[0] > 0.0)) &&
                            (e1 > 0.0 || (e1 == 0.0 && sign[1] > 0.0)) &&
                            (e2 > 0.0 || (e2 == 0.0 && sign[2] > 0.0));
        if (!inside) continue;
        const double sum = e0 + e1 + e2;
        const double w0 = e0 * v[0].inv_z, w1 = e1 * v[1].inv_z, w2 = e2 * v[2].inv_z;
        const double inv_z = (w0 + w1 + w2) / sum;
        if (!(inv_z > best_row[i])) continue;
        best_row[i] = inv_z;
        Hit& h = out_row[i];
        h.mesh = m, h.triangle = t;
        const double norm = 1.0 / (w0 + w1 + w2);
        h.b1 = w1 * norm, h.b2 = w2 * norm;
        if (want_t) {
          const double sx = (2.0 * px / W - 1.0) * cam_->tan_half_fov * cam_->aspect;
          const double sy = (1.0 - 2.0 * py / H) * cam_->tan_half_fov;
          h.t = glm::length(cam_->forward + sx * cam_->right + sy * cam_->up) / inv_z;
        }
      }
    }
  }
  for (size_t k = 0; k < n; ++k) out[k].hit = best[k] > 0.0;
}

}  // namespace xval
