// Images neither EXR nor PNG are decoded by OpenImageIO inside the module
// xval_oiio, loaded on the first such file only (image/other_formats.h);
// EXRs and PNGs never load it; a module that cannot be loaded is an error
// naming the file, what it is and the module.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "image/image.h"
#include "image/other_formats.h"
#include "support/temp_files.h"
#include "texture/texture.h"

using namespace xval;
namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

namespace {

// A 3x2 8-bit RGB texture of distinct codes, written by OpenImageIO in the
// format its extension names.
const std::vector<std::uint8_t> kCodes = {0, 1, 2, 250, 251, 252, 17, 34, 51, 128, 64, 32, 255, 0, 255, 9, 99, 199};

fs::path writeTexture(const fs::path& file) {
  OIIO::ImageSpec spec(3, 2, 3, OIIO::TypeDesc::UINT8);
  auto out = OIIO::ImageOutput::create(file.string());
  EXPECT_TRUE(out && out->open(file.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, kCodes.data()) &&
              out->close());
  return file;
}

}  // namespace

TEST(OtherFormats, TgaTextureLoadsThroughTheModule) {
  const fs::path dir = test::freshTempDir("xval_other_formats_tga");
  setOiioModulePathForTesting({});  // as a fresh process: the module beside the executable
  const Texture t = loadTextureImage(writeTexture(dir / "codes.tga"));
  EXPECT_EQ(t.width, 3);
  EXPECT_EQ(t.height, 2);
  EXPECT_EQ(t.rgb8, kCodes);
  EXPECT_FALSE(loadedOpenImageIoVersion().empty()) << "a TGA was decoded without the module";
}

TEST(OtherFormats, ExrAndPngNeverLoadTheModule) {
  const fs::path dir = test::freshTempDir("xval_other_formats_own");
  setOiioModulePathForTesting({});
  Image img(4, 3, true);
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = float(i % 7) / 7.0f;
  writeImage(img, dir / "a.exr");
  writeImage(img, dir / "a.png");
  readImage(dir / "a.exr");
  readImage(dir / "a.png");
  loadTextureImage(dir / "a.png");
  EXPECT_EQ(loadedOpenImageIoVersion(), "");
}

TEST(OtherFormats, AMissingModuleIsAnErrorNamingFileFormatAndModule) {
  const fs::path dir = test::freshTempDir("xval_other_formats_missing");
  const fs::path tga = writeTexture(dir / "codes.tga");
  const fs::path module = dir / "no_such_folder" / "xval_oiio.so";
  setOiioModulePathForTesting(module);
  std::string message;
  try {
    loadTextureImage(tga);
  } catch (const std::runtime_error& e) {
    message = e.what();
  }
  setOiioModulePathForTesting({});
  ASSERT_FALSE(message.empty()) << "the texture loaded without the module";
  EXPECT_NE(message.find(tga.string()), std::string::npos) << message;
  EXPECT_NE(message.find("extension \".tga\""), std::string::npos) << message;
  EXPECT_NE(message.find(module.string()), std::string::npos) << message;
  EXPECT_NE(message.find("cannot be loaded"), std::string::npos) << message;
}
