// Texture image I/O through OpenImageIO.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <stdexcept>

#include "files/atomic_write.h"
#include "image/image.h"
#include "image/image_header.h"
#include "scene/scene_limits.h"
#include "texture/brick.h"
#include "texture/texture.h"

namespace xval {

namespace OIIO = OIIO_NAMESPACE;

namespace {
// The file name OpenImageIO chooses an embedded image's reader by: from
// its first bytes (JPEG's FF D8 FF, else PNG: a PNG reader refuses
// anything that does not start with PNG's signature).
std::string embeddedImageName(const std::vector<std::uint8_t>& b) {
  return b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF ? "embedded.jpg" : "embedded.png";
}

// `file` names the image in messages; `embedded`, when given, holds its
// encoded bytes, read instead of the file.
Texture readTextureImage(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded) {
  // Stored values: OpenImageIO multiplies colour by alpha on reading unless
  // told that the caller wants the file's unassociated values.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
  if (embedded) {
    memory = std::make_unique<OIIO::Filesystem::IOMemReader>(embedded->data(), embedded->size());
    // The readers take the proxy from the configuration.
    void* proxy = memory.get();
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
  }
  auto in = embedded ? OIIO::ImageInput::open(embeddedImageName(*embedded), &config, memory.get())
                     : OIIO::ImageInput::open(file.string(), &config);
  const std::string what = embedded ? file.string() + " (embedded image)" : file.string();
  if (!in)
    throw std::runtime_error(what + ": cannot read texture image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  // The header is checked before anything is allocated (the scene loader
  // checked it too; the file may have changed since).
  const std::string problem = imageHeaderProblem({spec.width, spec.height, spec.depth, spec.nchannels},
                                                 textureLimits());
  if (!problem.empty()) throw std::runtime_error(what + ": texture image " + problem);
  Texture t;
  t.width = spec.width;
  t.height = spec.height;
  // Only the channels used are read: R, G, B, or the one grey channel
  // (alpha and any further channels are dropped).
  const int nc = spec.nchannels >= 3 ? 3 : 1;
  const size_t texels = size_t(t.width) * t.height;
  auto read = [&](OIIO::TypeDesc type, void* data) {
    if (!in->read_image(0, 0, 0, nc, type, data))
      throw std::runtime_error(what + ": cannot decode texture image: " + in->geterror());
  };
  // Replicates grey (and grey + alpha) to R, G, B.
  auto rgb = [nc](const auto& px, auto& out) {
    out.resize(px.size() / nc * 3);
    for (size_t i = 0; i < out.size() / 3; ++i)
      for (int c = 0; c < 3; ++c) out[i * 3 + c] = px[i * nc + (nc == 3 ? c : 0)];
  };
  t.rgb.resize(texels * 3);
  if (spec.format == OIIO::TypeDesc::UINT8) {
    std::vector<unsigned char> px(texels * nc);
    read(OIIO::TypeDesc::UINT8, px.data());
    rgb(px, t.rgb8);
    for (size_t i = 0; i < t.rgb.size(); ++i) t.rgb[i] = float(t.rgb8[i]) / 255.0f;
  } else if (spec.format == OIIO::TypeDesc::UINT16) {
    std::vector<std::uint16_t> px(texels * nc);
    read(OIIO::TypeDesc::UINT16, px.data());
    rgb(px, t.rgb16);
    for (size_t i = 0; i < t.rgb.size(); ++i) t.rgb[i] = float(t.rgb16[i]) / 65535.0f;
  } else {
    // Other formats (float, half, 32-bit) as OpenImageIO converts them.
    std::vector<float> px(texels * nc);
    read(OIIO::TypeDesc::FLOAT, px.data());
    rgb(px, t.rgb);
  }
  // Integer codes are finite and at most 1; a float image may hold anything.
  for (size_t i = 0; i < t.rgb.size(); ++i)
    if (!(std::abs(t.rgb[i]) <= kMaxTexelValue))
      throw std::runtime_error(what + ": texel (" + std::to_string(i / 3 % t.width) + ", " +
                               std::to_string(i / 3 / t.width) + ") has the value " + std::to_string(t.rgb[i]) +
                               "; expected a finite value of magnitude at most " +
                               std::to_string(kMaxTexelValue));
  return t;
}
}  // namespace

Texture loadTextureImage(const std::filesystem::path& file) { return readTextureImage(file, nullptr); }

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
  if (spec.source == TextureSpec::Source::Model)
    throw std::runtime_error("texture source \"model\" has no one texture: it is resolved per primitive of the "
                             "model file (geometry/model_textures.h) before textures are loaded");
  Texture t = spec.source == TextureSpec::Source::Brick ? makeBrickTexture()
              : spec.embedded                           ? readTextureImage(spec.path, spec.embedded.get())
                                                        : loadTextureImage(spec.path);
  t.pack();
  return t;
}

namespace {
// The textures writeTexturePng has encoded, with their PNG bytes.
struct EncodedTexture {
  int width = 0, height = 0;
  bool is8 = true;
  std::string codes;  // the code values' bytes
  std::string png;
};
struct TexturePngMemo {
  std::mutex lock;
  std::vector<EncodedTexture> entries;
  size_t bytes = 0;
};
TexturePngMemo& texturePngMemo() {
  static TexturePngMemo memo;
  return memo;
}

std::string readWholeFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) throw std::runtime_error(file.string() + ": cannot read back the PNG just written");
  return bytes;
}
}  // namespace

void writeTexturePng(const Texture& t, const std::filesystem::path& file) {
  const size_t n = size_t(t.width) * t.height * 3;
  const bool is8 = t.rgb8.size() == n, is16 = !is8 && t.rgb16.size() == n;
  if (!is8 && !is16)
    throw std::runtime_error(file.string() + ": texture has no 8-bit or 16-bit codes to write");
  const OIIO::TypeDesc type = is8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16;
  const void* data = is8 ? static_cast<const void*>(t.rgb8.data()) : t.rgb16.data();
  const std::string_view codes(static_cast<const char*>(data), n * (is8 ? 1 : 2));
  TexturePngMemo& memo = texturePngMemo();
  std::optional<std::string> kept;
  {
    std::lock_guard<std::mutex> hold(memo.lock);
    for (const EncodedTexture& e : memo.entries)
      if (e.width == t.width && e.height == t.height && e.is8 == is8 && e.codes == codes) kept = e.png;
  }
  if (kept) {
    // Written outside the lock (a write is synced to disk). Our own writer
    // checks every write (files/atomic_write.h); the bytes decoded whole
    // when they were encoded.
    writeFileAtomically(file, *kept);
    return;
  }
  std::string png;
  writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) throw std::runtime_error("cannot create PNG: " + OIIO::geterror());
    OIIO::ImageSpec spec(t.width, t.height, 3, type);
    spec.attribute("png:compressionLevel", kPngZlibLevel);
    spec.attribute("png:filter", kPngFilter);
    if (!out->open(tmp.string(), spec) || !out->write_image(type, data) || !out->close())
      throw std::runtime_error("cannot write PNG: " + out->geterror());
    requireDecodable(tmp, t.width, t.height);
    png = readWholeFile(tmp);
    return true;
  });
  std::lock_guard<std::mutex> hold(memo.lock);
  if (memo.bytes + codes.size() + png.size() > kTexturePngMemoBytes) return;
  for (const EncodedTexture& e : memo.entries)
    if (e.width == t.width && e.height == t.height && e.is8 == is8 && e.codes == codes) return;  // another thread's
  memo.bytes += codes.size() + png.size();
  memo.entries.push_back({t.width, t.height, is8, std::string(codes), std::move(png)});
}

}  // namespace xval
