// Visibility by rasterisation: the fast path's answer to "which triangle
// does the ray through this sample point hit first?", for every sample of a
// band of rows at once, without a ray query per sample.
//
// Only for cameras in front of all geometry: every vertex must have a view
// depth z = (P - eye) . forward > 0 (applicable() tells; otherwise the
// renderer traces Embree packets instead and says so in RenderStats).
//
// The math (camera/camera.h inverted): for a vertex P, d = P - eye,
//   z = d . forward,  x_px = (d . right / (z tan(fov/2) aspect) + 1) W / 2,
//   y_px = (1 - d . up / (z tan(fov/2))) H / 2,
// so the sample at image point (x, y) lies inside the projected triangle
// exactly when the camera ray through (x, y) crosses the triangle.
// Inside test: edge functions E_uw(p) = cross(P_w - P_u, p - P_u) in
// screen space, each edge evaluated from its lower vertex index so that
// the two triangles sharing an edge compute bit-identical values of
// opposite sign; a sample exactly on an edge belongs to the one triangle
// whose winding runs the edge from its lower index (when both face the same
// way on screen): no gaps, no double hits (watertight).
// Depth: 1/z is affine in screen space, 1/z(p) = sum_k l_k / z_k with the
// screen-space barycentrics l_k = E_k / sum E; the nearest hit has the
// largest 1/z. The perspective-correct barycentrics of the hit, the b1, b2
// the shading uses, are b_k = (l_k / z_k) / (1/z(p)).
// All of it in double: on x86 scalar double arithmetic costs what float
// does, and float pixel coordinates (ulp 6e-5 px at x = 720) would move the
// barycentrics of a 3-pixel triangle by ~1e-5, a visible texture shift.
// The per-band loop runs SIMD across the samples of a row (render/
// raster_band.h: Google Highway, the widest instruction set the CPU has),
// with every sample's arithmetic exactly as written above.
// Ray length to the hit (diagnostics only): t = z(p) |forward + sx right +
// sy up|.
// Back faces: a mesh flagged in `cull_back` (geometry/front_faces.h: its
// first hits are always front faces) has its back faces dropped when
// binning. With y down the image, a triangle whose winding normal faces the
// eye has signed area (x1 - x0)(y2 - y0) - (y1 - y0)(x2 - x0) < 0, so
// those with area > 0 are dropped (area 0 covers no sample anyway).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "render/accel.h"

namespace xval {

class Rasteriser {
 public:
  // True when every vertex of every mesh is in front of the camera.
  static bool applicable(const std::vector<TriangleMesh>& meshes, const CameraRays& cam);

  // Projects the vertices and bins the triangles into bands of band_rows
  // rows (done once per frame).
  // cull_back: per mesh, empty for none. threads: how many threads may
  // share the work (the result is the same on any number).
  Rasteriser(const std::vector<TriangleMesh>& meshes, const CameraRays& cam, int band_rows,
             const std::vector<bool>& cull_back = {}, int threads = 1);

  int bands() const { return int(bins_.size()); }
  // Band b's triangles, (mesh << 32) | triangle, in the order rasterised.
  const std::vector<std::uint64_t>& bin(int band) const { return bins_[band]; }
  size_t culledTriangles() const { return culled_; }

  // The first hits of a band's samples, one array per field (what the
  // raster writes, render/raster_band.h): sample k is hit where best[k] > 0,
  // by triangle key[k] = (mesh << 32) | triangle at b1[k], b2[k], ray length
  // t[k] (when asked for). Sized for band_rows rows by visibility.
  struct BandHits {
    std::vector<double> best, b1, b2, t;
    std::vector<std::uint64_t> key;
    bool hit(size_t k) const { return best[k] > 0.0; }
  };

  // The first hit of every sample (i + ox, j + oy) of band b's rows (ox, oy
  // in [0, 1): the sample's offset inside its pixel), row-major, W per row.
  void visibility(int band, double ox, double oy, bool want_t, BandHits& out) const;
  // The same as Hits: out.size() >= band_rows * W. No hit: Hit::hit = false.
  void visibility(int band, double ox, double oy, bool want_t, std::vector<Hit>& out) const;

  struct Vertex {
    double x, y, inv_z;  // pixels, 1 / view depth
  };

 private:
  const std::vector<TriangleMesh>* meshes_;
  const CameraRays* cam_;
  int band_rows_;
  size_t culled_ = 0;
  std::vector<std::vector<Vertex>> projected_;          // per mesh, per vertex
  std::vector<std::vector<std::uint64_t>> bins_;        // per band: (mesh << 32) | triangle
};

// The samples k in [0, count) of a band's hits (Rasteriser::visibility)
// that hit mesh `mesh`, in ascending k (render/raster_band.cpp): at[c] = k, tri[c] = its triangle,
// b1[c], b2[c] its barycentrics as float (float(double), to nearest);
// returns how many. SIMD across samples: each output array needs count +
// kCompactPad elements (whole vectors are stored).
inline constexpr size_t kCompactPad = 16;
size_t compactBandHits(const Rasteriser::BandHits& hits, size_t count, std::uint32_t mesh, std::uint32_t* at,
                       std::uint32_t* tri, float* b1, float* b2);

}  // namespace xval
