// Texture: an RGB image of stored values, looked up with wrap addressing.
//
// Values are the image's stored code values scaled to [0,1] (8-bit: c/255),
// never linearised. Addressing follows glTF: uv (0,0) is the top-left
// corner of the image, u runs right, v runs down; texel (ix, iy) has its
// centre at ((ix + 0.5)/W, (iy + 0.5)/H). Wrap: only frac(u), frac(v) count.
//   nearest:  ix = floor(frac(u) W), iy = floor(frac(v) H)
//   bilinear: x = frac(u) W - 0.5, x0 = floor(x), wx = x - x0 (same in y),
//             the four texels (x0, x0+1) x (y0, y0+1) taken modulo W, H;
//   trilinear on this one texture (level 0 of its mip chain,
//             texture/mip_chain.h): the bilinear lookup.
#pragma once

#include <glm/glm.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image_header.h"
#include "scene/scene.h"
#include "scene/scene_limits.h"

namespace xval {

struct Texture {
  int width = 0, height = 0;
  std::vector<float> rgb;  // row 0 = top of the image, 3 floats per texel
  std::vector<unsigned char> rgb8;  // the 8-bit codes when the source had them
  std::vector<std::uint16_t> rgb16;  // the 16-bit codes when the source had them
  // A compact copy for lookups, filled by pack(): one 32-bit word of codes
  // per texel, decoded through code_value. A 512 x 512 texture takes 1 MiB
  // instead of 3 MiB of floats, so it stays in a core's L2 cache; texel()
  // returns bit-identical values either way.
  std::vector<std::uint32_t> packed;
  std::array<float, 256> code_value{};
  // Set by pack() when every code that occurs has code_value[c] == c / 255
  // (float division, correctly rounded): a SIMD lookup may then decode by
  // dividing instead of through the table, with the same values
  // (shading/batch_shader.cpp).
  bool codes_are_c_over_255 = false;

  // Fills `packed` when every rgb value is the same function of its 8-bit
  // code (true for 8-bit sources); otherwise leaves it empty.
  void pack();

  glm::vec3 texel(int x, int y) const {
    const size_t at = size_t(y) * width + x;
    if (!packed.empty()) {
      const std::uint32_t c = packed[at];
      return {code_value[c & 255u], code_value[(c >> 8) & 255u], code_value[(c >> 16) & 255u]};
    }
    const float* p = &rgb[at * 3];
    return {p[0], p[1], p[2]};
  }

  template <class T>
  glm::vec<3, T> lookup(glm::vec<2, T> uv, TextureFilter f) const {
    T fu = uv.x - std::floor(uv.x), fv = uv.y - std::floor(uv.y);
    if (!(fu >= T(0) && fu <= T(1))) fu = T(0);  // NaN: a non-finite u
    if (!(fv >= T(0) && fv <= T(1))) fv = T(0);
    if (f == TextureFilter::Nearest) {
      int ix = std::min(int(fu * width), width - 1);
      int iy = std::min(int(fv * height), height - 1);
      return glm::vec<3, T>(texel(ix, iy));
    }
    T x = fu * width - T(0.5), y = fv * height - T(0.5);
    T x0f = std::floor(x), y0f = std::floor(y);
    T wx = x - x0f, wy = y - y0f;
    int x0 = int(x0f), y0 = int(y0f);
    int x1 = x0 + 1, y1 = y0 + 1;
    if (x0 < 0) x0 += width;
    if (y0 < 0) y0 += height;
    if (x1 >= width) x1 -= width;
    if (y1 >= height) y1 -= height;
    using V = glm::vec<3, T>;
    V top = V(texel(x0, y0)) * (T(1) - wx) + V(texel(x1, y0)) * wx;
    V bottom = V(texel(x0, y1)) * (T(1) - wx) + V(texel(x1, y1)) * wx;
    return top * (T(1) - wy) + bottom * wy;
  }
};

// Loads an image file: PNG (libpng), EXR (OpenEXR: R, G, B or its one
// channel) or any format OpenImageIO reads (through its module,
// image/other_formats.h). 8-bit and
// 16-bit integer images keep their code values c, and rgb = c / 255 or
// c / 65535 (float division); R, G, B are the stored values, never
// multiplied by alpha; alpha is dropped; grey is replicated. Throws
// std::runtime_error naming the file on failure.
Texture loadTextureImage(const std::filesystem::path& file);

// The texture a material uses (brick generated in code, or its image).
Texture loadTexture(const TextureSpec& spec);

// The texture limits of scene/scene_limits.h (kMaxTextureSide,
// kMaxTexturePixels) as image/image_header.h checks them: the loader checks
// a texture's header with them, and loadTextureImage again.
inline ImageLimits textureLimits() { return {kMaxTextureSide, kMaxTexturePixels, "texels"}; }

// Writes an RGB PNG holding exactly the texture's code values: 8-bit for
// textures with 8-bit codes, 16-bit for those with 16-bit codes (others
// are refused). The PNG encoding of each distinct texture is done once per
// process and its bytes kept (up to kTexturePngMemoBytes in all): a scene
// set's exports write the same few textures again and again (the reference
// set: 100 texture files of 7 distinct textures), and writing those bytes
// costs a fraction of encoding them. A texture is matched by its size, bit
// depth and every code value.
void writeTexturePng(const Texture& t, const std::filesystem::path& file);
inline constexpr size_t kTexturePngMemoBytes = size_t(64) << 20;

}  // namespace xval
