// The rasteriser's inner loop (render/raster.h has the math): every
// triangle of one band's bin against the band's samples, SIMD across the
// samples of a row (Highway's run-time dispatch). Each sample is computed
// with the same double operations in the same order on every instruction
// set, so the result does not depend on the CPU (test
// Renderer.RasterBandIsTheSameOnEveryInstructionSet).
#pragma once

#include <cstdint>
#include <vector>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "render/accel.h"
#include "render/raster.h"

namespace xval {

struct RasterBand {
  const std::vector<TriangleMesh>* meshes;
  const std::vector<std::vector<Rasteriser::Vertex>>* projected;
  const std::vector<std::uint64_t>* bin;  // (mesh << 32) | triangle
  const CameraRays* cam;
  int row0, row1;  // rows [row0, row1)
  double ox, oy;   // the sample's offset inside its pixel
    // Per sample of the band, row-major, (row1 - row0 + 1) * width + kRasterPad
  // each (whole SIMD vectors of two rows are read at the band's end): the
  // largest 1/z so far (0 = none; in: all 0), and where it is > 0 the hit's
  // (mesh << 32) | triangle, b1, b2 and, when t is not null, its ray length.
  double* best;
  std::uint64_t* key;
  double *b1, *b2, *t;
};

// Extra elements each per-sample array must have past the band's rows and
// one more row (whole SIMD vectors of two rows are read at the end of a
// row and of the band).
inline constexpr size_t kRasterPad = 16;

void rasterBand(const RasterBand& job);

}  // namespace xval
