// Gouraud shading in POV-Ray, as values before any SDL or PNG is written.
//
// An image holding, per triangle, a 2x2 texel block
// (c0, c1 / c2, c1 + c2 - c0) and uv at the three texel centres of c0, c1,
// c2. Bilinear interpolation (`interpolate 2`) over such a block is the
// affine function c0 + s (c1 - c0) + t (c2 - c0), and POV-Ray's mesh uv is
// barycentric, so the colour is the exact barycentric interpolation of the
// vertex colours. Measured alternatives: a mesh2 texture_list is up to
// 230/65535 off along triangle edges (POV-Ray weights three textures with
// single-precision smooth-triangle distances); an OpenEXR image_map is read
// as half floats (up to 16/65535 off). So the colours go into two 16-bit
// PNGs, coarse and fine, exact to ~1e-9: 16-bit codes relative to the
// per-channel range [lo, lo + range] of all texels,
//   c = lo + range (coarse + fine / 65535) / 65535,
// which the SDL reads back as an average of 7 parts (lo, and per channel
// the coarse and the fine code through a colour_map).
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "geometry/mesh.h"

namespace xval::pov {

struct GouraudImage {
  int width = 0, height = 0;
  std::vector<float> rgb;
  std::vector<glm::dvec2> uvs;  // 3 per triangle, POV-Ray's v (bottom-up)
};

GouraudImage gouraudImage(const TriangleMesh& m, const std::vector<glm::dvec3>& colours);

struct GouraudCodes {
  int width = 0, height = 0;
  glm::dvec3 lo{0.0}, range{1.0};
  std::vector<std::uint16_t> coarse, fine;  // 3 per texel, rows top-down
};

GouraudCodes gouraudCodes(const GouraudImage& g);

// Writes STEM_coarse.png and STEM_fine.png into dir and returns SDL
// declaring the pigment `name` that reads them back as the colours.
std::string gouraudPigment(const GouraudCodes& g, const std::filesystem::path& dir,
                           const std::string& stem, const std::string& name);

}  // namespace xval::pov
