// Texture image I/O through OpenImageIO.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <stdexcept>

#include "image/image_header.h"
#include "scene/scene_loader.h"
#include "texture/brick.h"
#include "texture/texture.h"

namespace xval {

namespace OIIO = OIIO_NAMESPACE;

Texture loadTextureImage(const std::filesystem::path& file) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in)
    throw std::runtime_error(file.string() + ": cannot read texture image: " +
                             OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  // The header is checked before anything is allocated (the scene loader
  // checked it too; the file may have changed since).
  const std::string problem = imageHeaderProblem({spec.width, spec.height, spec.depth, spec.nchannels},
                                                 textureLimits());
  if (!problem.empty()) throw std::runtime_error(file.string() + ": texture image " + problem);
  Texture t;
  t.width = spec.width;
  t.height = spec.height;
  // Only the channels used are read: R, G, B, or the one grey channel
  // (alpha and any further channels are dropped).
  const int nc = spec.nchannels >= 3 ? 3 : 1;
  const bool is8 = spec.format == OIIO::TypeDesc::UINT8;
  std::vector<float> px(size_t(t.width) * t.height * nc);
  // OIIO converts integer formats to float as code/(2^bits - 1), exactly
  // the stored-value convention the models use.
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, px.data()))
    throw std::runtime_error(file.string() + ": cannot decode texture image: " + in->geterror());
  for (size_t i = 0; i < px.size(); ++i)
    if (!(std::abs(px[i]) <= kMaxTexelValue))
      throw std::runtime_error(file.string() + ": texel (" + std::to_string(i / nc % t.width) + ", " +
                               std::to_string(i / nc / t.width) + ") has the value " + std::to_string(px[i]) +
                               "; expected a finite value of magnitude at most " +
                               std::to_string(kMaxTexelValue));
  std::vector<unsigned char> px8;
  if (is8) {
    px8.resize(px.size());
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::UINT8, px8.data()))
      throw std::runtime_error(file.string() + ": cannot decode texture image: " + in->geterror());
  }
  t.rgb.resize(size_t(t.width) * t.height * 3);
  if (is8) t.rgb8.resize(t.rgb.size());
  for (size_t i = 0; i < size_t(t.width) * t.height; ++i) {
    for (int c = 0; c < 3; ++c) {
      int sc = nc == 3 ? c : 0;  // grey (and grey+alpha) replicate
      t.rgb[i * 3 + c] = px[i * nc + sc];
      if (is8) t.rgb8[i * 3 + c] = px8[i * nc + sc];
    }
  }
  return t;
}

void Texture::pack() {
  packed.clear();
  codes_are_c_over_255 = false;
  const size_t n = size_t(width) * height;
  if (rgb8.size() != n * 3 || rgb.size() != n * 3) return;
  std::array<bool, 256> seen{};
  for (size_t i = 0; i < n * 3; ++i) {
    const unsigned c = rgb8[i];
    if (!seen[c]) seen[c] = true, code_value[c] = rgb[i];
    if (code_value[c] != rgb[i]) return;  // not a function of the code: keep floats
  }
  codes_are_c_over_255 = true;
  for (unsigned c = 0; c < 256; ++c)
    if (seen[c] && code_value[c] != float(c) / 255.0f) codes_are_c_over_255 = false;
  packed.resize(n);
  for (size_t i = 0; i < n; ++i)
    packed[i] = std::uint32_t(rgb8[i * 3]) | std::uint32_t(rgb8[i * 3 + 1]) << 8 |
                std::uint32_t(rgb8[i * 3 + 2]) << 16;
}

Texture loadTexture(const TextureSpec& spec) {
  Texture t = spec.source == TextureSpec::Source::Brick ? makeBrickTexture()
                                                        : loadTextureImage(spec.path);
  t.pack();
  return t;
}

void writeTexturePng(const Texture& t, const std::filesystem::path& file) {
  if (t.rgb8.size() != size_t(t.width) * t.height * 3)
    throw std::runtime_error(file.string() + ": texture has no 8-bit codes to write");
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out) throw std::runtime_error(file.string() + ": cannot create PNG: " + OIIO::geterror());
  OIIO::ImageSpec spec(t.width, t.height, 3, OIIO::TypeDesc::UINT8);
  if (!out->open(file.string(), spec) || !out->write_image(OIIO::TypeDesc::UINT8, t.rgb8.data()) ||
      !out->close())
    throw std::runtime_error(file.string() + ": cannot write PNG: " + out->geterror());
}

}  // namespace xval
