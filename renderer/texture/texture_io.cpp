// Texture image I/O: PNG through libpng, EXR through OpenEXR, other formats
// through the OpenImageIO module (image/other_formats.h).
#include <cmath>
#include <cstdio>
#include <type_traits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <stdexcept>

#include "files/atomic_write.h"
#include "image/image.h"
#include "image/exr_file.h"
#include "image/image_header.h"
#include "image/other_formats.h"
#include "image/png_file.h"
#include "scene/scene_limits.h"
#include "texture/brick.h"
#include "texture/texture.h"

namespace xval {

namespace {
// Replicates grey (and grey + alpha) to R, G, B: the first 3 channels, or
// the first one (alpha and any further channels are dropped).
template <class Sample> void rgbOf(const std::vector<Sample>& px, int channels, std::vector<Sample>& out) {
  const size_t nc = size_t(channels), texels = px.size() / nc;
  out.resize(texels * 3);
  for (size_t i = 0; i < texels; ++i)
    for (size_t c = 0; c < 3; ++c) out[i * 3 + c] = px[i * nc + (nc >= 3 ? c : 0)];
}

// A texture's codes: 8-bit codes c give rgb = c / 255, 16-bit c / 65535
// (float division); float samples are the values.
template <class Sample> void setCodes(Texture& t, const std::vector<Sample>& px, int channels) {
  if constexpr (std::is_same_v<Sample, std::uint8_t>) {
    rgbOf(px, channels, t.rgb8);
    t.rgb.resize(t.rgb8.size());
    for (size_t i = 0; i < t.rgb.size(); ++i) t.rgb[i] = float(t.rgb8[i]) / 255.0f;
  } else if constexpr (std::is_same_v<Sample, std::uint16_t>) {
    rgbOf(px, channels, t.rgb16);
    t.rgb.resize(t.rgb16.size());
    for (size_t i = 0; i < t.rgb.size(); ++i) t.rgb[i] = float(t.rgb16[i]) / 65535.0f;
  } else {
    rgbOf(px, channels, t.rgb);
  }
}

// An EXR texture: R, G, B, or its one channel as grey.
void readExrTexture(const std::filesystem::path& file, Texture& t, const std::string& what) {
  ExrInput in(file);
  const ImageHeader h = in.header();
  const std::string problem = imageHeaderProblem(h, textureLimits());
  if (!problem.empty()) throw std::runtime_error(what + ": texture image " + problem);
  t.width = h.width, t.height = h.height;
  const size_t texels = size_t(t.width) * t.height;
  std::vector<std::string> names;
  if (in.has("R") && in.has("G") && in.has("B")) names = {"R", "G", "B"};
  else if (in.channels().size() == 1) names = {in.channels()[0]};
  else throw std::runtime_error(what + ": an EXR texture needs channels R, G, B or exactly one channel");
  std::vector<float> px(texels * names.size());
  std::vector<ExrTarget> targets;
  for (size_t c = 0; c < names.size(); ++c)
    targets.push_back({names[c], px.data() + c, names.size(), size_t(t.width) * names.size()});
  in.read(targets);
  setCodes(t, px, int(names.size()));
}

// `file` names the image in messages; `embedded`, when given, holds its
// encoded bytes, read instead of the file.
Texture readTextureImage(const std::filesystem::path& file, const std::vector<std::uint8_t>* embedded) {
  const std::string what = embedded ? file.string() + " (embedded image)" : file.string();
  // The header is checked before anything is allocated (the scene loader
  // checked it too; the file may have changed since).
  auto check = [&](const ImageHeader& h) {
    const std::string problem = imageHeaderProblem(h, textureLimits());
    if (!problem.empty()) throw std::runtime_error(what + ": texture image " + problem);
  };
  unsigned char magic[8] = {};
  size_t got = 0;
  if (embedded) {
    for (; got < sizeof magic && got < embedded->size(); ++got) magic[got] = (*embedded)[got];
  } else if (std::FILE* f = std::fopen(file.c_str(), "rb")) {
    got = std::fread(magic, 1, sizeof magic, f);
    std::fclose(f);
  }
  Texture t;
  if (isPngSignature(magic, got)) {
    const PngPixels p = embedded ? decodePng(embedded->data(), embedded->size(), what, check)
                                 : readPngFile(file, check);
    t.width = p.width, t.height = p.height;
    if (p.bits == 16) setCodes(t, p.words, p.channels);
    else setCodes(t, p.bytes, p.channels);
  } else if (!embedded && isExrSignature(magic, got)) {
    readExrTexture(file, t, what);
  } else {
    const OtherFormatImage o = decodeOtherFormat(file, embedded, check);
    t.width = o.width, t.height = o.height;
    if (o.bits == 8) setCodes(t, o.u8, o.channels);
    else if (o.bits == 16) setCodes(t, o.u16, o.channels);
    else setCodes(t, o.f32, o.channels);
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

}  // namespace

void writeTexturePng(const Texture& t, const std::filesystem::path& file) {
  const size_t n = size_t(t.width) * t.height * 3;
  const bool is8 = t.rgb8.size() == n, is16 = !is8 && t.rgb16.size() == n;
  if (!is8 && !is16)
    throw std::runtime_error(file.string() + ": texture has no 8-bit or 16-bit codes to write");
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
  std::string png = encodePng(t.width, t.height, 3, is8 ? 8 : 16, data, {}, file.string());
  // The read-back (image/image.h, requireDecodable), from the bytes that
  // are then written, each write checked.
  requirePngDecodable(png, file.string(), t.width, t.height);
  writeFileAtomically(file, png);
  std::lock_guard<std::mutex> hold(memo.lock);
  if (memo.bytes + codes.size() + png.size() > kTexturePngMemoBytes) return;
  for (const EncodedTexture& e : memo.entries)
    if (e.width == t.width && e.height == t.height && e.is8 == is8 && e.codes == codes) return;  // another thread's
  memo.bytes += codes.size() + png.size();
  memo.entries.push_back({t.width, t.height, is8, std::string(codes), std::move(png)});
}

}  // namespace xval
