#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "files/atomic_write.h"
#include "image/image.h"
#include "image/image_header.h"
#include "scene/scene_limits.h"

namespace xval {

namespace OIIO = OIIO_NAMESPACE;

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

// Images are written and read in strips of this many rows through one
// buffer of a strip, not through a copy of the whole image: a render's EXR
// (up to 20 float channels, 41 MB at 720x720) would otherwise be a second
// and, read back, a third copy of the image in fresh memory, each page of
// it a page fault (docs/performance.md, "Where the time goes"). A multiple
// of every EXR compression's chunk height (PIZ: 32 rows), so each strip is
// whole chunks, which OpenEXR compresses on its threads side by side.
inline constexpr int kStripRows = 64;

// Reads the open image `in` (subimage 0, every channel, as float) strip by
// strip in order and hands each to use(first_row, rows, pixels): rows x
// width x nchannels floats, interleaved. False when a read fails
// (in->geterror() says why).
// A tiled file (another tool's EXR) is read whole, as one strip:
// OpenImageIO 2.4's read_scanlines stops such a process with a division by
// zero.
template <class Use> bool forEachStrip(OIIO::ImageInput& in, Use&& use) {
  const OIIO::ImageSpec& spec = in.spec();
  if (spec.tile_width > 0) {
    std::vector<float> all(size_t(spec.width) * spec.height * spec.nchannels);
    if (!in.read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data())) return false;
    use(0, spec.height, all.data());
    return true;
  }
  std::vector<float> strip(size_t(std::min(kStripRows, spec.height)) * spec.width * spec.nchannels);
  for (int y = 0; y < spec.height; y += kStripRows) {
    const int rows = std::min(kStripRows, spec.height - y);
    if (!in.read_scanlines(0, 0, spec.y + y, spec.y + y + rows, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                           strip.data()))
      return false;
    use(y, rows, strip.data());
  }
  return true;
}
}  // namespace

void requireDecodable(const std::filesystem::path& file, int width, int height) {
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error("written but unreadable: " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  if (spec.width != width || spec.height != height)
    throw std::runtime_error("written as " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                             ", expected " + std::to_string(width) + "x" + std::to_string(height));
  const bool whole = forEachStrip(*in, [&](int, int, const float*) {});
  if (!whole) throw std::runtime_error("written incompletely: " + in->geterror());
}

void writeImage(const Image& img, const std::filesystem::path& file, const char* exr_compression, Image* read_back) {
  const std::string name = file.string();
  const std::string ext = lower(file.extension().string());
  if (ext != ".exr" && ext != ".png")
    throw std::runtime_error(name + ": unsupported output extension \"" + ext +
                             "\" (expected .exr or .png)");
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  // Written whole or not at all (files/atomic_write.h).
  writeFileAtomically(file, [&](const std::filesystem::path& tmp_path) {
  const std::string tmp = tmp_path.string();
  auto out = OIIO::ImageOutput::create(tmp);
  if (!out) throw std::runtime_error("cannot create image writer: " + OIIO::geterror());
  const size_t n = size_t(img.width) * img.height;
  bool ok;
  if (ext == ".exr") {
    const bool raw = !img.raw.empty();
    const bool diag = !img.depth.empty();
    const bool albedo = diag && !img.albedo.empty();
    const bool texel = diag && img.texel_edge.size() == img.depth.size();
    const bool edge = diag && img.triangle_edge.size() == img.depth.size();
    std::vector<const std::vector<float>*> probes;  // kProbeChannels present, in order
    for (const DiagnosticsChannel& c : kProbeChannels)
      if (diag && (img.*c.member).size() == img.depth.size()) probes.push_back(&(img.*c.member));
    OIIO::ImageSpec spec(img.width, img.height,
                         4 + (raw ? 3 : 0) + (diag ? 3 : 0) + (albedo ? 3 : 0) + (texel ? 1 : 0) + (edge ? 1 : 0) +
                             int(probes.size()),
                         OIIO::TypeDesc::FLOAT);
    spec.channelnames = {"R", "G", "B", "A"};
    if (raw) spec.channelnames.insert(spec.channelnames.end(), {"raw.R", "raw.G", "raw.B"});
    if (diag) {
      spec.channelnames.insert(spec.channelnames.end(), {"Z", "backfacing", "incidence"});
      if (albedo) spec.channelnames.insert(spec.channelnames.end(), {"albedo.R", "albedo.G", "albedo.B"});
      if (texel) spec.channelnames.push_back("texel_edge");
      if (edge) spec.channelnames.push_back("triangle_edge");
      for (const DiagnosticsChannel& c : kProbeChannels)
        if ((img.*c.member).size() == img.depth.size()) spec.channelnames.push_back(c.name);
      spec.z_channel = 4 + (raw ? 3 : 0);
    }
    spec.alpha_channel = 3;
    spec.attribute("compression", exr_compression);
    // The colour channels hold display-referred code values: the models
    // work on stored texture codes and no transfer function is applied
    // (docs/scene-format.md), so a value of 0.5 is meant to be shown as the
    // code 0.5, as the 2012 shader's render target showed it. OpenEXR has
    // no attribute for that, and OpenImageIO 2.4 drops oiio:ColorSpace when
    // it writes an EXR (and reads every EXR back as "Linear"; measured with
    // oiiotool --attrib oiio:ColorSpace sRGB): the encoding is said in
    // xval:encoding, which every EXR and PNG xval writes carries.
    spec.attribute("xval:encoding", kColourEncoding);
    // Strip by strip (kStripRows): pixel i's channels at buf[(i - first) * nc].
    const size_t nc = size_t(spec.nchannels);
    std::vector<float> buf(size_t(std::min(kStripRows, img.height)) * img.width * nc);
    ok = out->open(tmp, spec);
    for (int y = 0; ok && y < img.height; y += kStripRows) {
      const int rows = std::min(kStripRows, img.height - y);
      const size_t first = size_t(y) * img.width;
      for (size_t i = first; i < first + size_t(rows) * img.width; ++i) {
        float* px = &buf[(i - first) * nc];
        std::copy_n(&img.rgba[i * 4], 4, px);
        if (raw) std::copy_n(&img.raw[i * 3], 3, px + 4);
        if (diag) {
          px[spec.z_channel] = img.depth[i];
          px[spec.z_channel + 1] = img.backfacing[i];
          px[spec.z_channel + 2] = img.incidence[i];
          if (albedo)
            for (int c = 0; c < 3; ++c) px[spec.z_channel + 3 + c] = img.albedo[i * 3 + c];
          if (texel) px[spec.z_channel + 3 + (albedo ? 3 : 0)] = img.texel_edge[i];
          if (edge) px[spec.z_channel + 3 + (albedo ? 3 : 0) + (texel ? 1 : 0)] = img.triangle_edge[i];
          float* first_probe = px + nc - probes.size();
          for (size_t k = 0; k < probes.size(); ++k) first_probe[k] = (*probes[k])[i];
        }
      }
      ok = out->write_scanlines(y, y + rows, 0, OIIO::TypeDesc::FLOAT, buf.data());
    }
  } else {
    // RGBA, 16 bits. PNG's alpha is unassociated: the stored colour is
    // the premultiplied colour divided by the coverage (0 where nothing is
    // hit), clamped to [0,1], so a reader that associates it again (OIIO does)
    // gets colour = stored x alpha back, within half a step.
    OIIO::ImageSpec spec(img.width, img.height, 4, OIIO::TypeDesc::UINT16);
    spec.alpha_channel = 3;
    // The buffer below is already unassociated: without this OpenImageIO
    // would take it as premultiplied and divide by alpha again.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    spec.attribute("xval:encoding", kColourEncoding);
    spec.attribute("png:compressionLevel", kPngZlibLevel);
    spec.attribute("png:filter", kPngFilter);
    std::vector<uint16_t> buf(n * 4);
    auto code = [](float v) { return uint16_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 65535.0f)); };
    for (size_t i = 0; i < n; ++i) {
      const float a = std::clamp(img.rgba[i * 4 + 3], 0.0f, 1.0f);
      for (int c = 0; c < 3; ++c) buf[i * 4 + c] = a > 0.0f ? code(img.rgba[i * 4 + c] / a) : 0;
      buf[i * 4 + 3] = code(a);
    }
    ok = out->open(tmp, spec) && out->write_image(OIIO::TypeDesc::UINT16, buf.data());
  }
  ok = out->close() && ok;
  if (!ok) throw std::runtime_error("cannot write image: " + out->geterror());
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
  writeFileAtomically(file, [&](const std::filesystem::path& tmp) {
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) throw std::runtime_error("cannot create PNG: " + OIIO::geterror());
    OIIO::ImageSpec spec(w, h, 3, OIIO::TypeDesc::UINT8);
    spec.attribute("png:compressionLevel", kPngZlibLevel);
    spec.attribute("png:filter", kPngFilter);
    bool ok = out->open(tmp.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, px.data());
    ok = out->close() && ok;
    if (!ok) throw std::runtime_error("cannot write PNG: " + out->geterror());
    requireDecodable(tmp, w, h);
    return true;
  });
}

ImageHeader readImageHeader(const std::filesystem::path& file) {
  requireRegularImageFile(file);
  auto in = OIIO::ImageInput::open(file.string());
  if (!in) throw std::runtime_error(file.string() + ": cannot open image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  return {spec.width, spec.height, spec.depth, spec.nchannels};
}

ImageLimits readImageLimits(int expect_width, int expect_height) {
  ImageLimits l{kMaxImageSide, kMaxImagePixels, "pixels", kMaxReadImageChannels};
  l.expect_width = expect_width, l.expect_height = expect_height;
  return l;
}

Image readImage(const std::filesystem::path& file, int expect_width, int expect_height) {
  const std::string name = file.string();
  requireRegularImageFile(file);
  // Formats whose alpha is unassociated (PNG) are read as stored, whatever
  // OpenImageIO's default, and associated below: the Image holds colour
  // premultiplied by coverage, as EXR stores it.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(name, &config);
  if (!in) throw std::runtime_error(name + ": cannot open image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  // The header's size is checked before the pixels are allocated.
  const std::string problem = imageHeaderProblem({spec.width, spec.height, spec.depth, spec.nchannels},
                                                 readImageLimits(expect_width, expect_height));
  if (!problem.empty()) throw std::runtime_error(name + ": the image " + problem);
  const int nc = spec.nchannels;
  auto channel = [&spec](const char* c) {
    for (int i = 0; i < spec.nchannels; ++i)
      if (spec.channelnames[i] == c) return i;
    return -1;
  };
  int ch[4] = {channel("R"), channel("G"), channel("B"), channel("A")};
  if (ch[0] < 0 || ch[1] < 0 || ch[2] < 0)
    throw std::runtime_error(name + ": image has no R, G, B channels");
  int raw[3] = {channel("raw.R"), channel("raw.G"), channel("raw.B")};
  bool has_raw = raw[0] >= 0 && raw[1] >= 0 && raw[2] >= 0;
  Image img(spec.width, spec.height, has_raw);
  img.has_alpha = ch[3] >= 0;
  const bool unassociated = img.has_alpha && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0;
  int zc = channel("Z"), bc = channel("backfacing"), ic = channel("incidence");
  int ac[3] = {channel("albedo.R"), channel("albedo.G"), channel("albedo.B")};
  const bool diag = zc >= 0 && bc >= 0 && ic >= 0;
  const bool albedo = diag && ac[0] >= 0 && ac[1] >= 0 && ac[2] >= 0;
  img.depth.assign(diag ? size_t(spec.width) * spec.height : 0, 0.0f);
  img.backfacing.assign(img.depth.size(), 0.0f);
  img.incidence.assign(img.depth.size(), 0.0f);
  img.albedo.assign(albedo ? img.depth.size() * 3 : 0, 0.0f);
  const int tc = channel("texel_edge");  // absent from EXRs older than it: left empty
  img.texel_edge.assign(diag && tc >= 0 ? img.depth.size() : 0, kFarFromTexelEdge);
  const int ec = channel("triangle_edge");  // likewise
  img.triangle_edge.assign(diag && ec >= 0 ? img.depth.size() : 0, kFarFromTriangleEdge);
  std::vector<std::pair<int, std::vector<float>*>> probes;  // kProbeChannels in the file: likewise
  for (const DiagnosticsChannel& c : kProbeChannels) {
    const int pc = channel(c.name);
    (img.*c.member).assign(diag && pc >= 0 ? img.depth.size() : 0, 0.0f);
    if (diag && pc >= 0) probes.emplace_back(pc, &(img.*c.member));
  }
  // Strip by strip (forEachStrip): pixel i's channels at px.
  const bool whole = forEachStrip(*in, [&](int y, int rows, const float* strip) {
    const size_t first = size_t(y) * spec.width;
    for (size_t i = first; i < first + size_t(rows) * spec.width; ++i) {
      const float* px = strip + (i - first) * size_t(nc);
      if (diag) {
        img.depth[i] = px[zc];
        img.backfacing[i] = px[bc];
        img.incidence[i] = px[ic];
        if (albedo)
          for (int c = 0; c < 3; ++c) img.albedo[i * 3 + c] = px[ac[c]];
        if (!img.texel_edge.empty()) img.texel_edge[i] = px[tc];
        if (!img.triangle_edge.empty()) img.triangle_edge[i] = px[ec];
        for (const auto& [pc, v] : probes) (*v)[i] = px[pc];
      }
      for (int c = 0; c < 4; ++c) img.rgba[i * 4 + c] = ch[c] >= 0 ? px[ch[c]] : 1.0f;
      if (unassociated)
        for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] *= img.rgba[i * 4 + 3];
      if (has_raw)
        for (int c = 0; c < 3; ++c) img.raw[i * 3 + c] = px[raw[c]];
    }
  });
  if (!whole) throw std::runtime_error(name + ": cannot read image: " + in->geterror());
  return img;
}

}  // namespace xval
