// Texture files: the stored code values are read (RGB never multiplied by
// alpha, 8-bit and 16-bit), and the exporters' texture.png carries exactly
// those codes at the source's bit depth.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "support/temp_files.h"
#include "common/export_common.h"
#include "texture/texture.h"

using namespace xval;
namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

namespace {

fs::path freshDir(const std::string& name) { return test::freshTempDir("xval_texture_io_" + name); }

// A 5x3 RGBA image (codes out of `max`): opaque, fully transparent and
// partly transparent texels with colours far from their premultiplied
// values; the first is the texel (65263, 2609, 1440, alpha 716) scaled to
// the bit depth.
std::vector<std::uint16_t> rgbaCodes(unsigned max) {
  auto s = [max](unsigned c16) { return std::uint16_t((c16 * max + 32767) / 65535); };
  const unsigned texels[15][4] = {
      {65263, 2609, 1440, 716}, {65535, 65535, 65535, 0}, {40000, 20000, 10000, 65535},
      {1, 2, 3, 0},             {65535, 0, 32768, 1000},  {12345, 54321, 33333, 65535},
      {0, 0, 0, 0},             {65535, 65535, 65535, 65535}, {30000, 30001, 30002, 300},
      {258, 257, 256, 65534},   {7, 65000, 129, 0},       {65535, 1, 65535, 40000},
      {500, 5000, 50000, 9},    {2, 65533, 4, 65535},     {33000, 100, 64000, 1}};
  std::vector<std::uint16_t> out;
  for (const auto& t : texels)
    for (unsigned c : t) out.push_back(s(c));
  return out;
}

// Writes the codes as a 4-channel PNG of `type`, the values as stored
// (OpenImageIO is told they are not premultiplied, so it writes them as
// they are).
void writeRgba(const fs::path& file, const std::vector<std::uint16_t>& codes, OIIO::TypeDesc type) {
  OIIO::ImageSpec spec(5, 3, 4, type);
  spec.attribute("oiio:UnassociatedAlpha", 1);
  std::vector<unsigned char> c8(codes.begin(), codes.end());
  auto out = OIIO::ImageOutput::create(file.string());
  ASSERT_TRUE(out && out->open(file.string(), spec));
  ASSERT_TRUE(out->write_image(type, type == OIIO::TypeDesc::UINT8 ? static_cast<const void*>(c8.data())
                                                                    : codes.data()));
  ASSERT_TRUE(out->close());
}

// The RGB codes of a 3-channel image file, and its format.
std::vector<std::uint16_t> readRgbCodes(const fs::path& file, OIIO::TypeDesc& format) {
  auto in = OIIO::ImageInput::open(file.string());
  EXPECT_TRUE(in) << file;
  if (!in) return {};
  format = in->spec().format;
  EXPECT_EQ(in->spec().nchannels, 3) << file;
  std::vector<std::uint16_t> px(size_t(in->spec().width) * in->spec().height * 3);
  // Read as 16-bit: an 8-bit code c reads as 257 c exactly.
  EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, px.data()));
  return px;
}

void expectStoredRgb(unsigned max, OIIO::TypeDesc type) {
  const fs::path dir = freshDir(std::to_string(max));
  const fs::path file = dir / "rgba.png";
  const std::vector<std::uint16_t> codes = rgbaCodes(max);
  writeRgba(file, codes, type);
  const Texture t = loadTextureImage(file);
  ASSERT_EQ(t.width, 5);
  ASSERT_EQ(t.height, 3);
  const std::vector<std::uint16_t> stored =
      max == 255 ? std::vector<std::uint16_t>(t.rgb8.begin(), t.rgb8.end()) : t.rgb16;
  ASSERT_EQ(stored.size(), 45u) << "the " << max << " codes are kept";
  for (size_t i = 0; i < 15; ++i)
    for (int c = 0; c < 3; ++c) {
      const unsigned want = codes[i * 4 + c], alpha = codes[i * 4 + 3];
      EXPECT_EQ(stored[i * 3 + c], want) << "texel " << i << " channel " << c << " alpha " << alpha;
      EXPECT_EQ(t.rgb[i * 3 + c], float(want) / float(max)) << "texel " << i << " channel " << c;
    }

  // Both exporters copy the texture through exportTexture: texture.png
  // holds the same RGB codes at the source's depth.
  Scene s;
  s.material.texture = TextureSpec{};
  s.material.texture->source = TextureSpec::Source::Image;
  s.material.texture->path = file;
  const fs::path out_dir = dir / "export";
  fs::create_directories(out_dir);
  ASSERT_TRUE(exportTexture(s, out_dir));
  OIIO::TypeDesc format;
  const std::vector<std::uint16_t> exported = readRgbCodes(out_dir / "texture.png", format);
  EXPECT_EQ(format, type);
  ASSERT_EQ(exported.size(), 45u);
  const unsigned scale = max == 255 ? 257 : 1;
  for (size_t i = 0; i < 15; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(exported[i * 3 + c], codes[i * 4 + c] * scale) << "exported texel " << i << " channel " << c;
  fs::remove_all(dir);
}

}  // namespace

TEST(TextureIo, Rgba8IsReadAndExportedAsStored) { expectStoredRgb(255, OIIO::TypeDesc::UINT8); }
TEST(TextureIo, Rgba16IsReadAndExportedAsStored) { expectStoredRgb(65535, OIIO::TypeDesc::UINT16); }

// A float image has no integer codes to copy losslessly: refused, saying
// which file and why.
TEST(TextureIo, FloatTexturesAreRefusedByTheExporters) {
  const fs::path dir = freshDir("float");
  const fs::path file = dir / "grey.exr";
  {
    OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::FLOAT);
    const float px[12] = {0.25f, 0.5f, 0.75f, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out && out->open(file.string(), spec) && out->write_image(OIIO::TypeDesc::FLOAT, px) &&
                out->close());
  }
  EXPECT_EQ(loadTextureImage(file).rgb[1], 0.5f);
  Scene s;
  s.material.texture = TextureSpec{};
  s.material.texture->source = TextureSpec::Source::Image;
  s.material.texture->path = file;
  try {
    exportTexture(s, dir);
    ADD_FAILURE() << "a float texture was exported";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find("grey.exr"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("16-bit"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// writeTexturePng encodes each distinct texture once per process and writes
// its kept bytes again: every file still holds exactly its own texture's
// codes. Textures differing in one code, in bit depth alone (the same
// values as 8 and as 16 bits) or in shape alone (the same codes as 4x2 and
// 2x4) each get their own PNG, and a texture written again gets the
// same bytes as the first time.
TEST(TextureIo, EachTextureFileHoldsItsOwnCodesWhenEncodingsAreKept) {
  const fs::path dir = freshDir("memo");
  auto make8 = [](int w, int h, unsigned char first) {
    Texture t;
    t.width = w, t.height = h;
    for (int i = 0; i < w * h * 3; ++i) t.rgb8.push_back((unsigned char)(i * 37 + 11));
    t.rgb8[0] = first;
    return t;
  };
  Texture a = make8(4, 2, 5), b = make8(4, 2, 6), c = make8(2, 4, 5);
  Texture a16 = a;
  a16.rgb16.assign(a.rgb8.begin(), a.rgb8.end());
  a16.rgb8.clear();
  const std::vector<std::pair<const Texture*, std::string>> writes = {
      {&a, "a1.png"}, {&b, "b.png"}, {&c, "c.png"}, {&a16, "a16.png"}, {&a, "a2.png"}, {&c, "c2.png"}};
  for (const auto& [t, name] : writes) writeTexturePng(*t, dir / name);
  for (const auto& [t, name] : writes) {
    OIIO::TypeDesc format;
    const std::vector<std::uint16_t> got = readRgbCodes(dir / name, format);
    const bool is8 = !t->rgb8.empty();
    EXPECT_EQ(format, is8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::UINT16) << name;
    auto in = OIIO::ImageInput::open((dir / name).string());
    ASSERT_TRUE(in) << name;
    EXPECT_EQ(in->spec().width, t->width) << name;
    ASSERT_EQ(got.size(), size_t(t->width) * t->height * 3) << name;
    for (size_t i = 0; i < got.size(); ++i)
      ASSERT_EQ(got[i], is8 ? unsigned(t->rgb8[i]) * 257 : unsigned(t->rgb16[i])) << name << " code " << i;
  }
  auto bytes = [&](const char* name) {
    std::ifstream in(dir / name, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  };
  EXPECT_EQ(bytes("a1.png"), bytes("a2.png"));
  EXPECT_EQ(bytes("c.png"), bytes("c2.png"));
  fs::remove_all(dir);
}
