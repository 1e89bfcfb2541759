// Image write/read round trips (EXR through OpenEXR, PNG through libpng).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "image/image.h"
#include "image/image_header.h"
#include "support/temp_files.h"

using namespace xval;

namespace {
Image sample() {
  Image img(7, 5, true);
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = float(i % 13) / 7.0f - 0.3f;
  for (size_t i = 0; i < img.raw.size(); ++i) img.raw[i] = float(i) * 0.37f - 2.0f;
  return img;
}
std::filesystem::path tmp(const char* name) {
  static const std::filesystem::path dir = xval::test::freshTempDir("xval_image_io");
  return dir / name;
}
}  // namespace

TEST(ImageIo, ExrRoundTripIsExactAndUnclamped) {
  Image a = sample();
  writeImage(a, tmp("xval_rt.exr"));
  Image b = readImage(tmp("xval_rt.exr"));
  EXPECT_EQ(b.width, 7);
  EXPECT_EQ(b.height, 5);
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.raw, b.raw);
  // No temporary (files/atomic_write.h: xval_rt.exr.partial-<pid>-<n>/) is left.
  for (const auto& e : std::filesystem::directory_iterator(tmp("xval_rt.exr").parent_path()))
    EXPECT_NE(e.path().filename().string().rfind("xval_rt.exr.partial", 0), 0u) << e.path();
}

// A render's pixels: coverage alpha in [0,1] (0 and 1 included) and a
// premultiplied colour <= alpha, as the renderer writes them.
Image coverageSample() {
  Image img(7, 5, false);
  for (size_t i = 0; i < size_t(7 * 5); ++i) {
    const float a = i % 5 == 0 ? 0.0f : i % 5 == 1 ? 1.0f : float(i % 7) / 7.0f + 0.05f;
    img.rgba[i * 4 + 3] = a;
    for (int c = 0; c < 3; ++c) img.rgba[i * 4 + c] = a * float((i * 3 + c) % 11) / 10.0f;
  }
  return img;
}

// Every EXR codec xval writes with is lossless: a full-channel image of
// arbitrary finite floats (all exponents, both signs, subnormals, zeros)
// reads back bit for bit, and the file names the codec. A lossy codec
// (pxr24, b44, dwaa) in either constant fails this.
TEST(ImageIo, EveryExrCompressionReadsBackBitForBit) {
  Image a(33, 17, true);
  uint32_t state = 12345;
  auto next = [&state] { return state = state * 1664525u + 1013904223u; };
  auto anyFinite = [&] {
    for (;;) {
      const uint32_t bits = next();
      float f;
      std::memcpy(&f, &bits, sizeof f);
      if (std::isfinite(f)) return f;
    }
  };
  for (auto* v : {&a.rgba, &a.raw, &a.depth, &a.backfacing, &a.incidence, &a.albedo, &a.texel_edge, &a.triangle_edge})
    for (float& f : *v) f = anyFinite();
  for (const DiagnosticsChannel& c : kProbeChannels)
    for (float& f : a.*c.member) f = anyFinite();
  a.rgba[0] = 0.0f, a.rgba[1] = -0.0f, a.rgba[2] = std::numeric_limits<float>::denorm_min();
  auto sameBits = [](const std::vector<float>& x, const std::vector<float>& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) == 0);
  };
  for (const char* codec : {kRenderExrCompression, kDifferenceExrCompression}) {
    const std::filesystem::path f = tmp((std::string("xval_codec_") + std::string(codec).substr(0, 3) + ".exr").c_str());
    writeImage(a, f, codec);
    auto in = OIIO::ImageInput::open(f.string());
    ASSERT_TRUE(in) << codec;
    const std::string stored = in->spec().get_string_attribute("compression");
    EXPECT_EQ(std::string(codec).rfind(stored, 0), 0u) << codec << " stored as " << stored;
    const Image b = readImage(f);
    EXPECT_TRUE(sameBits(a.rgba, b.rgba)) << codec;
    EXPECT_TRUE(sameBits(a.raw, b.raw)) << codec;
    EXPECT_TRUE(sameBits(a.depth, b.depth)) << codec;
    EXPECT_TRUE(sameBits(a.backfacing, b.backfacing)) << codec;
    EXPECT_TRUE(sameBits(a.incidence, b.incidence)) << codec;
    EXPECT_TRUE(sameBits(a.albedo, b.albedo)) << codec;
    EXPECT_TRUE(sameBits(a.texel_edge, b.texel_edge)) << codec;
    EXPECT_TRUE(sameBits(a.triangle_edge, b.triangle_edge)) << codec;
    for (const DiagnosticsChannel& c : kProbeChannels) EXPECT_TRUE(sameBits(a.*c.member, b.*c.member)) << codec << " " << c.name;
  }
}

// Images are written and read in strips of rows (image_io.cpp kStripRows,
// 64): an image of several strips, the last one partial, reads back bit for
// bit, every channel, as EXR; and its PNG decodes to the same size.
TEST(ImageIo, ImagesOfSeveralStripsReadBackWhole) {
  Image a(3, 150, true);
  for (auto* v : {&a.rgba, &a.raw, &a.depth, &a.backfacing, &a.incidence, &a.albedo, &a.texel_edge, &a.triangle_edge})
    for (size_t i = 0; i < v->size(); ++i) (*v)[i] = float(i) * 0.25f + float(v->size());
  for (const DiagnosticsChannel& c : kProbeChannels)
    for (size_t i = 0; i < (a.*c.member).size(); ++i) (a.*c.member)[i] = float(i) + 0.5f;
  writeImage(a, tmp("xval_strips.exr"));
  const Image b = readImage(tmp("xval_strips.exr"));
  EXPECT_EQ(a.rgba, b.rgba);
  EXPECT_EQ(a.raw, b.raw);
  EXPECT_EQ(a.depth, b.depth);
  EXPECT_EQ(a.albedo, b.albedo);
  EXPECT_EQ(a.triangle_edge, b.triangle_edge);
  for (const DiagnosticsChannel& c : kProbeChannels) EXPECT_EQ(a.*c.member, b.*c.member) << c.name;
  writeImage(a, tmp("xval_strips.png"));
  const Image p = readImage(tmp("xval_strips.png"));
  EXPECT_EQ(p.width, 3);
  EXPECT_EQ(p.height, 150);
}

// A tiled EXR (another tool's; xval writes scanlines) is read whole: the
// strips' read_scanlines stopped the process on one (SIGFPE in
// OpenImageIO 2.4).
TEST(ImageIo, TiledExrReadsBack) {
  const std::filesystem::path f = tmp("xval_tiled.exr");
  const int w = 20, h = 70;
  std::vector<float> px(size_t(w) * h * 4);
  for (size_t i = 0; i < px.size(); ++i) px[i] = float(i % 97) / 97.0f;
  {
    auto out = OIIO::ImageOutput::create(f.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(w, h, 4, OIIO::TypeDesc::FLOAT);
    spec.tile_width = spec.tile_height = 16;
    spec.alpha_channel = 3;
    ASSERT_TRUE(out->open(f.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
    ASSERT_TRUE(out->close());
  }
  const Image b = readImage(f);
  EXPECT_EQ(b.width, w);
  EXPECT_EQ(b.height, h);
  EXPECT_EQ(b.rgba, px);
}

// PNG keeps the coverage: 16-bit RGBA, the colour stored unassociated
// (colour / alpha) and associated again on reading. Alpha and fully covered
// pixels come back within half a step; a partly covered pixel's colour
// within half a step of the stored colour times the read alpha, i.e.
// |q(c/a) a' - c| <= 0.5/65535 a' + (c/a) |a' - a| <= 1/65535.
TEST(ImageIo, Png16RoundTripKeepsAlpha) {
  Image a = coverageSample();
  writeImage(a, tmp("xval_rt.png"));
  Image b = readImage(tmp("xval_rt.png"));
  ASSERT_EQ(b.width, 7);
  EXPECT_TRUE(b.has_alpha);
  const float step = 1.0f / 65535.0f, eps = 1e-7f;
  for (size_t i = 0; i < size_t(7 * 5); ++i) {
    const float alpha = a.rgba[i * 4 + 3];
    EXPECT_NEAR(b.rgba[i * 4 + 3], alpha, 0.5f * step + eps) << i;
    const bool whole = alpha == 0.0f || alpha == 1.0f;
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(b.rgba[i * 4 + c], a.rgba[i * 4 + c], (whole ? 0.5f : 1.0f) * step + eps) << i << " " << c;
  }
}

TEST(ImageIo, UnsupportedExtensionIsAnError) {
  try {
    writeImage(sample(), tmp("xval_rt.jpg"));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("xval_rt.jpg"), std::string::npos);
  }
}

// The preview of a thin image keeps every pixel: 2000 x 1 at most 360 px
// wide is k = 6 blocks, ceil(2000/6) = 334 x 1 (not 333 x 0), and the last
// column averages the two pixels of its partial block (1998 and 1999).
TEST(ImageIo, PreviewOfAThinImageKeepsEveryPixel) {
  Image img(2000, 1, false);
  for (int x = 0; x < 2000; ++x)
    for (int c = 0; c < 3; ++c) img.pixel(x, 0)[c] = x >= 1998 ? 1.0f : 0.0f;
  writePreviewPng(img, tmp("xval_thin.png"), 360);
  const ImageHeader h = readImageHeader(tmp("xval_thin.png"));
  EXPECT_EQ(h.width, 334);
  EXPECT_EQ(h.height, 1);
  const Image p = readImage(tmp("xval_thin.png"));
  EXPECT_FLOAT_EQ(p.pixel(333, 0)[0], 1.0f);  // mean of the in-bounds pixels 1998, 1999
  EXPECT_FLOAT_EQ(p.pixel(332, 0)[0], 0.0f);
}

// Every EXR and PNG xval writes says what its colour channels hold in
// xval:encoding (OpenEXR has no attribute for a transfer function and
// OpenImageIO 2.4 reads every EXR as "Linear"); the PNG reads as sRGB,
// which the codes are, with its alpha.
TEST(ImageIo, EveryImageSaysItsColourEncoding) {
  const Image a = sample();
  for (const char* name : {"xval_enc.exr", "xval_enc.png"}) {
    writeImage(a, tmp(name));
    auto in = OIIO::ImageInput::open(tmp(name).string());
    ASSERT_TRUE(in) << name;
    EXPECT_EQ(in->spec().get_string_attribute("xval:encoding"), std::string(kColourEncoding)) << name;
    EXPECT_EQ(in->spec().nchannels >= 4, true) << name;
  }
  auto png = OIIO::ImageInput::open(tmp("xval_enc.png").string());
  EXPECT_EQ(png->spec().get_string_attribute("oiio:ColorSpace"), "sRGB");
  EXPECT_EQ(png->spec().alpha_channel, 3);
}

// The read-back of a written EXR (requireDecodable) decompresses every
// chunk although it copies out one channel: a file cut short, or whose
// end a full disk left as zeros, is refused; the intact file passes.
TEST(ImageIo, ReadBackRefusesAnExrCutShortOrZeroedAtTheEnd) {
  Image img(300, 200, true);  // several chunks of every channel
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = float((i * 7919) % 1000) / 999.0f;
  for (size_t i = 0; i < img.raw.size(); ++i) img.raw[i] = float((i * 104729) % 777) / 7.0f;
  for (size_t i = 0; i < img.depth.size(); ++i) img.depth[i] = float(i % 301) + 0.5f;
  const std::filesystem::path whole = tmp("readback_whole.exr");
  writeImage(img, whole);
  EXPECT_NO_THROW(requireDecodable(whole, 300, 200));
  std::string bytes;
  {
    std::ifstream in(whole, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_GT(bytes.size(), 10000u);
  auto write = [](const std::filesystem::path& f, const std::string& b) {
    std::ofstream(f, std::ios::binary).write(b.data(), std::streamsize(b.size()));
  };
  const std::filesystem::path cut = tmp("readback_cut.exr"), zeroed = tmp("readback_zeroed.exr");
  write(cut, bytes.substr(0, bytes.size() * 2 / 3));
  std::string z = bytes;
  std::fill(z.begin() + std::ptrdiff_t(z.size() * 2 / 3), z.end(), '\0');
  write(zeroed, z);
  EXPECT_THROW(requireDecodable(cut, 300, 200), std::runtime_error);
  EXPECT_THROW(requireDecodable(zeroed, 300, 200), std::runtime_error);
}
