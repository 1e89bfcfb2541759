#include "common/supersample.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/export_common.h"
#include "scene_file/scene_budget.h"
#include "scene_file/scene_loader.h"
#include "shading/models.h"

namespace xval {

SubpixelGrid subpixelGrid(const Scene& scene) {
  const int spp = scene.render.spp;
  const int n = int(std::lround(std::sqrt(double(spp))));
  const std::string field = "render.spp = " + std::to_string(spp);
  if (spp < 1 || spp > kMaxSpp || n * n != spp)
    throw ExportError(field + ": expected a perfect square from 1 to " + std::to_string(kMaxSpp) +
                      " (an n x n grid of samples per pixel)");
  SubpixelGrid g{n, scene.camera.width * n, scene.camera.height * n};
  if (n == 1) return g;
  const std::string size = field + ": rendered as " + std::to_string(n) + " x " + std::to_string(n) +
                           " samples per pixel, the external renderer's image is " + std::to_string(g.width) +
                           "x" + std::to_string(g.height);
  const long long pixels = (long long)g.width * g.height;
  if (g.width > kMaxImageSide || g.height > kMaxImageSide || pixels > kMaxImagePixels)
    throw ExportError(size + "; an image read back is at most " + std::to_string(kMaxImageSide) + " on a side and " +
                      std::to_string(kMaxImagePixels) + " pixels in all: lower spp or the resolution");
  const long long mb = (kBytesPerPixel * pixels + (1 << 20) - 1) >> 20;
  if (mb > Budget{}.max_memory_mb)
    throw ExportError(size + ", about " + std::to_string(mb) + " MiB at " + std::to_string(kBytesPerPixel) +
                      " bytes a pixel; the memory budget is " + std::to_string(Budget{}.max_memory_mb) +
                      " MiB: lower spp or the resolution");
  return g;
}

Image boxFilter(const Image& fine, int n) {
  if (n < 1 || fine.width % n != 0 || fine.height % n != 0)
    throw std::invalid_argument("boxFilter: a " + std::to_string(fine.width) + "x" + std::to_string(fine.height) +
                                " image is not made of " + std::to_string(n) + " x " + std::to_string(n) + " blocks");
  const int W = fine.width / n, H = fine.height / n;
  const bool raw = !fine.raw.empty();
  Image out(W, H, false);
  if (raw) out.raw.assign(size_t(W) * H * 3, 0.0f);
  out.has_alpha = fine.has_alpha;
  const double inv = 1.0 / (double(n) * n);
  for (int j = 0; j < H; ++j)
    for (int i = 0; i < W; ++i) {
      double c[4] = {0, 0, 0, 0}, r[3] = {0, 0, 0};
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          const size_t at = size_t(n * j + sy) * fine.width + size_t(n * i + sx);
          for (int q = 0; q < 3; ++q) c[q] += models::saturate(double(fine.rgba[at * 4 + q]));
          c[3] += fine.rgba[at * 4 + 3];
          if (raw)
            for (int q = 0; q < 3; ++q) r[q] += fine.raw[at * 3 + q];
        }
      const size_t to = size_t(j) * W + i;
      for (int q = 0; q < 4; ++q) out.rgba[to * 4 + q] = float(c[q] * inv);
      if (raw)
        for (int q = 0; q < 3; ++q) out.raw[to * 3 + q] = float(r[q] * inv);
    }
  return out;
}

}  // namespace xval
