// Compiled once per SIMD target (Highway's foreach_target.h re-includes
// this file); rasterBand picks the best target the CPU has.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "render/raster_band.cpp"
#include <hwy/foreach_target.h>  // must come before highway.h
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

#include "render/pixel_index.h"
#include "render/raster_band.h"

HWY_BEFORE_NAMESPACE();
namespace xval {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void RasterBandImpl(const RasterBand& job) {
  const hn::ScalableTag<double> d;
  using VD = hn::Vec<decltype(d)>;
  const size_t N = hn::Lanes(d);
  const CameraRays& cam = *job.cam;
  const int W = cam.width, H = cam.height;
  const int row0 = job.row0, row1 = job.row1;
  const double ox = job.ox, oy = job.oy;
  // The bounding box only has to contain every sample the exact edge test
  // accepts; the 1e-7 px slack covers the rounding of minx - ox.
  constexpr double kSlack = 1e-7;
  const VD zero = hn::Zero(d);
  const hn::RebindToUnsigned<decltype(d)> du;
  // A vector covers C columns of kRows rows: with 8 lanes 4 x 2, as the
  // bins' triangles are a few pixels wide (a row of 8 would leave most
  // lanes outside); with fewer lanes one row. Lane q's sample is at
  // column i + q % C, row j + q / C.
  constexpr size_t kRows = hn::MaxLanes(d) >= 8 ? 2 : 1;
  const size_t C = N / kRows;
  alignas(64) double cols[hn::MaxLanes(d)], rows[hn::MaxLanes(d)];
  for (size_t q = 0; q < N; ++q) cols[q] = double(q % C), rows[q] = double(q / C);
  const VD lane_col = hn::Load(d, cols), lane_row = hn::Load(d, rows);
  // A block's lanes in memory: one row, or two rows W apart (each half of
  // the vector stored under its half of the mask).
  const hn::Half<decltype(d)> dh;
  auto load = [&](const double* p) {
    if constexpr (kRows == 1) return hn::LoadU(d, p);
    else return hn::Combine(d, hn::LoadU(dh, p + W), hn::LoadU(dh, p));
  };
  auto store = [&](auto dv, auto v, auto mask, auto* p) {
    if constexpr (kRows == 1) {
      hn::BlendedStore(v, mask, dv, p);
    } else {
      const hn::Half<decltype(dv)> half;
      const auto m = hn::VecFromMask(dv, mask);
      hn::BlendedStore(hn::LowerHalf(half, v), hn::MaskFromVec(hn::LowerHalf(half, m)), half, p);
      hn::BlendedStore(hn::UpperHalf(half, v), hn::MaskFromVec(hn::UpperHalf(half, m)), half, p + W);
    }
  };

  for (std::uint64_t key : *job.bin) {
    const std::uint32_t m = std::uint32_t(key >> 32), t = std::uint32_t(key);
    const glm::u32vec3 tri = (*job.meshes)[m].triangles[t];
    const Rasteriser::Vertex* P = (*job.projected)[m].data();
    const Rasteriser::Vertex v[3] = {P[tri[0]], P[tri[1]], P[tri[2]]};
    const double minx = std::min({v[0].x, v[1].x, v[2].x}), maxx = std::max({v[0].x, v[1].x, v[2].x});
    const double miny = std::min({v[0].y, v[1].y, v[2].y}), maxy = std::max({v[0].y, v[1].y, v[2].y});
    // Clamped in double (pixel_index.h): a NaN start gives 0 and a NaN end
    // -1, an empty box.
    const int i0 = clampedIndex(std::ceil(minx - ox - kSlack), 0, W);
    const int i1 = clampedIndex(std::floor(maxx - ox + kSlack), -1, W - 1);
    const int j0 = clampedIndex(std::ceil(miny - oy - kSlack), row0, row1);
    const int j1 = clampedIndex(std::floor(maxy - oy + kSlack), row0 - 1, row1 - 1);
    if (i0 > i1 || j0 > j1) continue;  // no sample inside the box (or NaN)
    const double area = (v[1].x - v[0].x) * (v[2].y - v[0].y) - (v[1].y - v[0].y) * (v[2].x - v[0].x);
    if (!(area != 0.0)) continue;  // edge-on (or NaN): no sample sees it
    const double s = area > 0.0 ? 1.0 : -1.0;
    // Edge k is opposite vertex k: from u = vertex k+1 to w = vertex k+2,
    // evaluated from the lower vertex index (lo) towards the higher (hi):
    //   C_k(p) = ex (p.y - lo.y) - ey (p.x - lo.x),  e_k = sign_k C_k.
    // On the edge (e_k = 0) the sample belongs to the triangle with
    // sign_k > 0: the one that runs the edge from its lower index.
    double lx[3], ly[3], ex[3], ey[3], sign[3];
    for (int k = 0; k < 3; ++k) {
      const int u = (k + 1) % 3, w = (k + 2) % 3;
      const bool forward = tri[u] < tri[w];
      const Rasteriser::Vertex& lo = forward ? v[u] : v[w];
      const Rasteriser::Vertex& hi = forward ? v[w] : v[u];
      lx[k] = lo.x, ly[k] = lo.y, ex[k] = hi.x - lo.x, ey[k] = hi.y - lo.y;
      sign[k] = forward ? s : -s;
    }
    const auto key_v = hn::Set(du, key);
    const VD lx0 = hn::Set(d, lx[0]), lx1 = hn::Set(d, lx[1]), lx2 = hn::Set(d, lx[2]);
    const VD ey0 = hn::Set(d, ey[0]), ey1 = hn::Set(d, ey[1]), ey2 = hn::Set(d, ey[2]);
    const VD sg0 = hn::Set(d, sign[0]), sg1 = hn::Set(d, sign[1]), sg2 = hn::Set(d, sign[2]);
    const VD iz0 = hn::Set(d, v[0].inv_z), iz1 = hn::Set(d, v[1].inv_z), iz2 = hn::Set(d, v[2].inv_z);
    // inside_k: e_k > 0, or e_k >= 0 where sign_k > 0 (the tie rule).
    auto inside = [&](VD e, double sg) { return sg > 0.0 ? e >= zero : e > zero; };
    for (int j = j0; j <= j1; j += kRows) {
      // The block's samples: lane q at column i + q % C, row j + q / C.
      const VD row = hn::Set(d, double(j)) + lane_row;  // whole numbers, exact
      const VD py = row + hn::Set(d, oy);               // j + oy per lane, as one sample's
      const VD r0 = hn::Set(d, ex[0]) * (py - hn::Set(d, ly[0]));
      const VD r1 = hn::Set(d, ex[1]) * (py - hn::Set(d, ly[1]));
      const VD r2 = hn::Set(d, ex[2]) * (py - hn::Set(d, ly[2]));
      const auto rows_in = row <= hn::Set(d, double(j1));
      const size_t row_at = size_t(j - row0) * W;
      for (int i = i0; i <= i1; i += int(C)) {
        const VD col = hn::Set(d, double(i)) + lane_col;
        const VD px = col + hn::Set(d, ox);  // i + ox, exactly
        const VD e0 = sg0 * (r0 - ey0 * (px - lx0));
        const VD e1 = sg1 * (r1 - ey1 * (px - lx1));
        const VD e2 = sg2 * (r2 - ey2 * (px - lx2));
        auto in = hn::And(hn::And(rows_in, col <= hn::Set(d, double(i1))),
                          hn::And(inside(e0, sign[0]), hn::And(inside(e1, sign[1]), inside(e2, sign[2]))));
        if (hn::AllFalse(d, in)) continue;
        const VD sum = (e0 + e1) + e2;
        const VD w0 = e0 * iz0, w1 = e1 * iz1, w2 = e2 * iz2;
        const VD wsum = (w0 + w1) + w2;
        const VD inv_z = wsum / sum;
        const size_t at = row_at + size_t(i);
        in = hn::And(in, inv_z > load(job.best + at));
        if (hn::AllFalse(d, in)) continue;
        // The hit's barycentrics, b_k = w_k (1 / wsum), for every lane at
        // once (the same two double roundings as one sample at a time),
        // written with 1/z and the triangle's key where the sample is inside
        // and nearer.
        const VD norm = hn::Set(d, 1.0) / wsum;
        store(d, inv_z, in, job.best + at);
        store(d, w1 * norm, in, job.b1 + at);
        store(d, w2 * norm, in, job.b2 + at);
        store(du, key_v, hn::RebindMask(du, in), job.key + at);
        if (job.t) {
          alignas(64) double iz[HWY_MAX_BYTES / sizeof(double)];
          hn::Store(inv_z, d, iz);
          static_assert(HWY_MAX_BYTES / sizeof(double) <= 8, "one byte of mask bits");
          alignas(8) std::uint8_t bytes[8] = {};
          hn::StoreMaskBits(d, in, bytes);
          for (unsigned bits = bytes[0]; bits != 0; bits &= bits - 1) {
            const int q = __builtin_ctz(bits), x = i + q % int(C), y = j + q / int(C);
            const double sx = (2.0 * (x + ox) / W - 1.0) * cam.tan_half_fov * cam.aspect;
            const double sy = (1.0 - 2.0 * (y + oy) / H) * cam.tan_half_fov;
            job.t[size_t(y - row0) * W + size_t(x)] =
                glm::length(cam.forward + sx * cam.right + sy * cam.up) / iz[q];
          }
        }
      }
    }
  }
}

// compactBandHits: the hits on `mesh` in sample order, N samples at a time
// (compressed stores keep their order; the float conversion rounds as the
// scalar float(double) does, to nearest).
size_t CompactBandHitsImpl(const double* best, const std::uint64_t* key, const double* b1, const double* b2,
                           size_t count, std::uint32_t mesh, std::uint32_t* at, std::uint32_t* tri, float* b1f,
                           float* b2f) {
  const hn::ScalableTag<double> d;
  const hn::RebindToUnsigned<decltype(d)> du;
  const hn::Rebind<float, decltype(d)> df;
  const hn::Rebind<std::uint32_t, decltype(d)> d32;
  const size_t N = hn::Lanes(d);
  const auto want = hn::Set(du, std::uint64_t(mesh));
  size_t c = 0, k = 0;
  for (; k + N <= count; k += N) {
    const auto on_mesh = hn::Eq(hn::ShiftRight<32>(hn::LoadU(du, key + k)), want);
    const auto hit = hn::And(hn::LoadU(d, best + k) > hn::Zero(d), hn::RebindMask(d, on_mesh));
    if (hn::AllFalse(d, hit)) continue;
    // The mask in 32-bit lanes: all-ones lanes truncate to all-ones.
    const auto m32 = hn::Ne(hn::TruncateTo(d32, hn::BitCast(du, hn::VecFromMask(d, hit))), hn::Zero(d32));
    const auto mf = hn::RebindMask(df, m32);
    hn::CompressStore(hn::Iota(d32, std::uint32_t(k)), m32, d32, at + c);
    hn::CompressStore(hn::TruncateTo(d32, hn::LoadU(du, key + k)), m32, d32, tri + c);
    hn::CompressStore(hn::DemoteTo(df, hn::LoadU(d, b1 + k)), mf, df, b1f + c);
    c += hn::CompressStore(hn::DemoteTo(df, hn::LoadU(d, b2 + k)), mf, df, b2f + c);
  }
  for (; k < count; ++k) {
    if (!(best[k] > 0.0) || (key[k] >> 32) != mesh) continue;
    at[c] = std::uint32_t(k), tri[c] = std::uint32_t(key[k]), b1f[c] = float(b1[k]), b2f[c] = float(b2[k]);
    ++c;
  }
  return c;
}

}  // namespace HWY_NAMESPACE
}  // namespace xval
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace xval {
HWY_EXPORT(RasterBandImpl);
HWY_EXPORT(CompactBandHitsImpl);
void rasterBand(const RasterBand& job) { HWY_DYNAMIC_DISPATCH(RasterBandImpl)(job); }
size_t compactBandHits(const Rasteriser::BandHits& hits, size_t count, std::uint32_t mesh, std::uint32_t* at,
                       std::uint32_t* tri, float* b1, float* b2) {
  return HWY_DYNAMIC_DISPATCH(CompactBandHitsImpl)(hits.best.data(), hits.key.data(), hits.b1.data(),
                                                    hits.b2.data(), count, mesh, at, tri, b1, b2);
}
}  // namespace xval
#endif
