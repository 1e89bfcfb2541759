#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <type_traits>
#include <stdexcept>
#include <string>
#include <utility>

#include "files/atomic_write.h"
#include "image/exr_file.h"
#include "image/image.h"
#include "image/image_header.h"
#include "image/other_formats.h"
#include "image/png_file.h"
#include "scene/scene_limits.h"

namespace xval {

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}
}  // namespace

namespace {
enum class FileKind { Exr, Png, Other };

// Which decoder reads `file`: by its first bytes, not its name.
FileKind fileKind(const std::filesystem::path& file) {
  unsigned char magic[8] = {};
  size_t got = 0;
  if (std::FILE* f = std::fopen(file.c_str(), "rb")) {
    got = std::fread(magic, 1, sizeof magic, f);
    std::fclose(f);
  }
  return isExrSignature(magic, got) ? FileKind::Exr : isPngSignature(magic, got) ? FileKind::Png : FileKind::Other;
}

std::string sizeText(int w, int h) { return std::to_string(w) + "x" + std::to_string(h); }

void requireSize(const ImageHeader& h, int width, int height) {
  if (h.width != width || h.height != height)
    throw std::runtime_error("written as " + sizeText(h.width, h.height) + ", expected " + sizeText(width, height));
}

// Decodes every chunk of the EXR `file` whole: OpenEXR reads and
// decompresses each chunk (all channels of its rows) before it copies the
// requested channels out, so asking for one channel, into one reused row,
// checks every byte of the file as asking for all of them would, without
// converting the other channels' values (measured: the read-back of the
// Table 2 render's 20 channels, a tenth of `xval render`'s CPU, mostly
// OpenEXR's per-value copies).
void requireExrDecodable(const std::filesystem::path& file, int width, int height) {
  ExrInput in(file);
  requireSize(in.header(), width, height);
  if (in.channels().empty()) throw std::runtime_error(file.string() + ": written without a channel");
  std::vector<float> row(static_cast<size_t>(width));
  in.read({{in.channels().front(), row.data(), 1, 0}});
}
}  // namespace

namespace {
// Integer codes as float: c x (1 / max), the conversion every image read
// back has had (OpenImageIO's, bit for bit, before xval decoded PNGs itself).
inline float codeValue(std::uint8_t c) { return float(c) * (1.0f / 255.0f); }
inline float codeValue(std::uint16_t c) { return float(c) * (1.0f / 65535.0f); }

// readImage of decoded samples (PNG, or another format through
// other_formats.h): R, G, B, A by name, raw.* when present; alpha, when
// unassociated, multiplied in.
template <class Sample>
Image imageOfSamples(int width, int height, const std::vector<std::string>& names, const std::vector<Sample>& px,
                     bool unassociated, const std::string& name) {
  auto channel = [&names](const char* c) {
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == c) return int(i);
    return -1;
  };
  const int ch[4] = {channel("R"), channel("G"), channel("B"), channel("A")};
  if (ch[0] < 0 || ch[1] < 0 || ch[2] < 0) throw std::runtime_error(name + ": image has no R, G, B channels");
  const int raw[3] = {channel("raw.R"), channel("raw.G"), channel("raw.B")};
  const bool has_raw = raw[0] >= 0 && raw[1] >= 0 && raw[2] >= 0;
  Image img(width, height, has_raw);
  img.has_alpha = ch[3] >= 0;
  unassociated = unassociated && img.has_alpha;
  for (const DiagnosticsChannel& c : kProbeChannels) (img.*c.member).clear();
  img.depth.clear(), img.backfacing.clear(), img.incidence.clear(), img.albedo.clear();
  img.texel_edge.clear(), img.triangle_edge.clear();
  const size_t nc = names.size(), n = size_t(width) * size_t(height);
  auto value = [](Sample v) {
    if constexpr (std::is_same_v<Sample, float>) return v;
    else return codeValue(v);
  };
  for (size_t i = 0; i < n; ++i) {
    const Sample* p = &px[i * nc];
    for (int c = 0; c < 4; ++c) img.rgba[i * 4 + c] = ch[c] >= 0 ? value(p[ch[c]]) : 1.0f;
    if (unassociated)
      for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] *= img.rgba[i * 4 + 3];
    if (has_raw)
      for (int c = 0; c < 3; ++c) img.raw[i * 3 + c] = value(p[raw[c]]);
  }
  return img;
}

// PNG's channel names as OpenImageIO named them: grey "Y", grey + alpha
// "Y", "A", else R, G, B, A.
std::vector<std::string> pngChannelNames(int channels) {
  if (channels == 1) return {"Y"};
  if (channels == 2) return {"Y", "A"};
  std::vector<std::string> n = {"R", "G", "B", "A"};
  n.resize(size_t(channels));
  return n;
}

Image imageOfPng(const PngPixels& p, const std::string& name) {
  // PNG's alpha is unassociated.
  return p.bits == 16 ? imageOfSamples(p.width, p.height, pngChannelNames(p.channels), p.words, true, name)
                      : imageOfSamples(p.width, p.height, pngChannelNames(p.channels), p.bytes, true, name);
}

}  // namespace

void requireDecodable(const std::filesystem::path& file, int width, int height) {
  switch (fileKind(file)) {
    case FileKind::Exr:
      return requireExrDecodable(file, width, height);
    case FileKind::Png:
      readPngFile(file, [&](const ImageHeader& h) { requireSize(h, width, height); });
      return;
    case FileKind::Other:
      break;
  }
  throw std::runtime_error(file.string() + ": written but neither an EXR nor a PNG");
}

namespace {
// The EXR of writeImage: every channel straight from the Image's arrays.
void writeImageExr(const Image& img, const std::filesystem::path& file, const char* compression) {
  const size_t w = size_t(img.width);
  std::vector<ExrChannel> channels;
  auto add = [&](const char* name, const std::vector<float>& v, size_t stride, size_t offset) {
    channels.push_back({name, v.data() + offset, stride, w * stride});
  };
  const char* rgba[] = {"R", "G", "B", "A"};
  for (size_t c = 0; c < 4; ++c) add(rgba[c], img.rgba, 4, c);
  if (!img.raw.empty()) {
    const char* raw[] = {"raw.R", "raw.G", "raw.B"};
    for (size_t c = 0; c < 3; ++c) add(raw[c], img.raw, 3, c);
  }
  if (!img.depth.empty()) {
    add("Z", img.depth, 1, 0);
    add("backfacing", img.backfacing, 1, 0);
    add("incidence", img.incidence, 1, 0);
    if (!img.albedo.empty()) {
      const char* albedo[] = {"albedo.R", "albedo.G", "albedo.B"};
      for (size_t c = 0; c < 3; ++c) add(albedo[c], img.albedo, 3, c);
    }
    if (img.texel_edge.size() == img.depth.size()) add("texel_edge", img.texel_edge, 1, 0);
    if (img.triangle_edge.size() == img.depth.size()) add("triangle_edge", img.triangle_edge, 1, 0);
    for (const DiagnosticsChannel& c : kProbeChannels)
      if ((img.*c.member).size() == img.depth.size()) add(c.name, img.*c.member, 1, 0);
  }
  // The colour channels hold display-referred code values: the models
  // work on stored texture codes and no transfer function is applied
  // (docs/scene-format.md), so a value of 0.5 is meant to be shown as the
  // code 0.5, as the 2012 shader's render target showed it. OpenEXR has
  // no attribute for that: the encoding is said in xval:encoding, which
  // every EXR and PNG xval writes carries.
  writeExrFile(file, img.width, img.height, channels, compression, {{"xval:encoding", kColourEncoding}});
}
}  // namespace

void writeImage(const Image& img, const std::filesystem::path& file, const char* exr_compression, Image* read_back) {
  const std::string name = file.string();
  const std::string ext = lower(file.extension().string());
  if (ext != ".exr" && ext != ".png")
    throw std::runtime_error(name + ": unsupported output extension \"" + ext +
                             "\" (expected .exr or .png)");
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  if (ext == ".png") {
    // RGBA, 16 bits. PNG's alpha is unassociated: the stored colour is
    // the premultiplied colour divided by the coverage (0 where nothing is
    // hit), clamped to [0,1], so a reader that associates it again (readImage
    // does) gets colour = stored x alpha back, within half a step.
    const size_t n = size_t(img.width) * img.height;
    std::vector<uint16_t> buf(n * 4);
    auto code = [](float v) { return uint16_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f)); };
    for (size_t i = 0; i < n; ++i) {
      const float a = std::clamp(img.rgba[i * 4 + 3], 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c) buf[i * 4 + c] = a > 0.0f ? code(img.rgba[i * 4 + c] / a) : 0;
      buf[i * 4 + 3] = code(a);
    }
    const std::string png = encodePng(img.width, img.height, 4, 16, buf.data(), {{"xval:encoding", kColourEncoding}}, name);
    const PngPixels back = requirePngDecodable(png, name, img.width, img.height);
    if (read_back) *read_back = imageOfPng(back, name);
    writeFileAtomically(file, png);
    return;
  }
  // Written whole or not at all (files/atomic_write.h).
  writeFileAtomically(file, [&](const std::filesystem::path& tmp_path) {
    writeImageExr(img, tmp_path, exr_compression);
    // The read-back that checks the write is also the image handed back.
    if (read_back) *read_back = readImage(tmp_path, img.width, img.height);
    else requireDecodable(tmp_path, img.width, img.height);
    return true;
  });
}

// The preview is the image box-filtered by k x k blocks, k = ceil(longest
// side / max_side), so its longest side is at most max_side. Its size is
// ceil(W/k) x ceil(H/k): the last row and column average the pixels of their
// partial block that lie inside the image, so no pixel of the image is
// dropped and a thin image (H < k) still gives one row, never zero.
void writePreviewPng(const Image& img, const std::filesystem::path& file, int max_side) {
  if (img.width < 1 || img.height < 1 || max_side < 1)
    throw std::runtime_error(file.string() + ": cannot write a preview of a " + std::to_string(img.width) + "x" +
                             std::to_string(img.height) + " image at most " + std::to_string(max_side) +
                             " px wide (expected positive sizes)");
  const int k = std::max(1, (std::max(img.width, img.height) + max_side - 1) / max_side);
  const int w = (img.width + k - 1) / k, h = (img.height + k - 1) / k;
  std::vector<unsigned char> px(size_t(w) * h * 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int x1 = std::min(img.width, (x + 1) * k), y1 = std::min(img.height, (y + 1) * k);
      const int n = (x1 - x * k) * (y1 - y * k);
      for (int c = 0; c < 3; ++c) {
        double sum = 0;
        for (int sy = y * k; sy < y1; ++sy)
          for (int sx = x * k; sx < x1; ++sx) sum += std::clamp(img.pixel(sx, sy)[c], 0.0f, 1.0f);
        px[(size_t(y) * w + x) * 3 + c] = (unsigned char)std::lround(sum / n * 255.0);
      }
    }
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  const std::string png = encodePng(w, h, 3, 8, px.data(), {}, file.string());
  requirePngDecodable(png, file.string(), w, h);
  writeFileAtomically(file, png);
}

ImageHeader readImageHeader(const std::filesystem::path& file) {
  requireRegularImageFile(file);
  switch (fileKind(file)) {
    case FileKind::Exr:
      return ExrInput(file).header();
    case FileKind::Png:
      return readPngHeader(file);
    case FileKind::Other:
      break;
  }
  return otherFormatHeader(file);
}

ImageLimits readImageLimits(int expect_width, int expect_height) {
  ImageLimits l{kMaxImageSide, kMaxImagePixels, "pixels", kMaxReadImageChannels};
  l.expect_width = expect_width, l.expect_height = expect_height;
  return l;
}

namespace {
// readImage of an EXR: each channel read straight into the Image's arrays.
Image readImageExr(const std::filesystem::path& file, int expect_width, int expect_height) {
  const std::string name = file.string();
  ExrInput in(file);
  const ImageHeader header = in.header();
  // The header's size is checked before the pixels are allocated.
  const std::string problem = imageHeaderProblem(header, readImageLimits(expect_width, expect_height));
  if (!problem.empty()) throw std::runtime_error(name + ": the image " + problem);
  if (!in.has("R") || !in.has("G") || !in.has("B")) throw std::runtime_error(name + ": image has no R, G, B channels");
  const bool has_raw = in.has("raw.R") && in.has("raw.G") && in.has("raw.B");
  Image img(header.width, header.height, has_raw);
  const size_t w = size_t(img.width), n = w * size_t(img.height);
  std::vector<ExrTarget> targets;
  auto add = [&](const char* channel, std::vector<float>& v, size_t stride, size_t offset) {
    targets.push_back({channel, v.data() + offset, stride, w * stride});
  };
  img.has_alpha = in.has("A");
  const char* rgba[] = {"R", "G", "B", "A"};
  for (size_t c = 0; c < 4; ++c)
    if (c < 3 || img.has_alpha) add(rgba[c], img.rgba, 4, c);
  if (!img.has_alpha)
    for (size_t i = 0; i < n; ++i) img.rgba[i * 4 + 3] = 1.0f;
  if (has_raw) {
    const char* raw[] = {"raw.R", "raw.G", "raw.B"};
    for (size_t c = 0; c < 3; ++c) add(raw[c], img.raw, 3, c);
  }
  const bool diag = in.has("Z") && in.has("backfacing") && in.has("incidence");
  const bool albedo = diag && in.has("albedo.R") && in.has("albedo.G") && in.has("albedo.B");
  img.depth.assign(diag ? n : 0, 0.0f);
  img.backfacing.assign(img.depth.size(), 0.0f);
  img.incidence.assign(img.depth.size(), 0.0f);
  img.albedo.assign(albedo ? n * 3 : 0, 0.0f);
  // Channels absent from EXRs older than them are left empty.
  img.texel_edge.assign(diag && in.has("texel_edge") ? n : 0, kFarFromTexelEdge);
  img.triangle_edge.assign(diag && in.has("triangle_edge") ? n : 0, kFarFromTriangleEdge);
  for (const DiagnosticsChannel& c : kProbeChannels) (img.*c.member).assign(diag && in.has(c.name) ? n : 0, 0.0f);
  if (diag) {
    add("Z", img.depth, 1, 0);
    add("backfacing", img.backfacing, 1, 0);
    add("incidence", img.incidence, 1, 0);
    if (albedo) {
      const char* names[] = {"albedo.R", "albedo.G", "albedo.B"};
      for (size_t c = 0; c < 3; ++c) add(names[c], img.albedo, 3, c);
    }
    if (!img.texel_edge.empty()) add("texel_edge", img.texel_edge, 1, 0);
    if (!img.triangle_edge.empty()) add("triangle_edge", img.triangle_edge, 1, 0);
    for (const DiagnosticsChannel& c : kProbeChannels)
      if (!(img.*c.member).empty()) add(c.name, img.*c.member, 1, 0);
  }
  in.read(targets);
  return img;
}
}  // namespace

Image readImage(const std::filesystem::path& file, int expect_width, int expect_height) {
  const std::string name = file.string();
  requireRegularImageFile(file);
  // The header's size is checked before the pixels are allocated.
  auto check = [&](const ImageHeader& h) {
    const std::string problem = imageHeaderProblem(h, readImageLimits(expect_width, expect_height));
    if (!problem.empty()) throw std::runtime_error(name + ": the image " + problem);
  };
  switch (fileKind(file)) {
    case FileKind::Exr:
      return readImageExr(file, expect_width, expect_height);
    case FileKind::Png:
      return imageOfPng(readPngFile(file, check), name);
    case FileKind::Other:
      break;
  }
  // Formats whose alpha is unassociated (TIFF may be) are read as stored
  // and associated here: the Image holds colour premultiplied by coverage,
  // as EXR stores it.
  const OtherFormatImage o = decodeOtherFormat(file, nullptr, check);
  return o.bits == 8    ? imageOfSamples(o.width, o.height, o.names, o.u8, o.unassociated, name)
         : o.bits == 16 ? imageOfSamples(o.width, o.height, o.names, o.u16, o.unassociated, name)
                        : imageOfSamples(o.width, o.height, o.names, o.f32, o.unassociated, name);
}

}  // namespace xval
