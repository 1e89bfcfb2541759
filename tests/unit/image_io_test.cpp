// Image write/read round trips through OpenImageIO.
#include <gtest/gtest.h>

#include <filesystem>

#include "image/image.h"

using namespace xval;

namespace {
Image sample() {
  Image img(7, 5, true);
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = float(i % 13) / 7.0f - 0.3f;
  for (size_t i = 0; i < img.raw.size(); ++i) img.raw[i] = float(i) * 0.37f - 2.0f;
  return img;
}
std::filesystem::path tmp(const char* name) {
  return std::filesystem::temp_directory_path() / name;
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
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::temp_directory_path()))
    EXPECT_NE(e.path().filename().string().rfind("xval_rt.exr.partial", 0), 0u) << e.path();
}

TEST(ImageIo, Png16RoundTripWithinHalfAStep) {
  Image a = sample();
  writeImage(a, tmp("xval_rt.png"));
  Image b = readImage(tmp("xval_rt.png"));
  ASSERT_EQ(b.width, 7);
  for (size_t i = 0; i < size_t(7 * 5); ++i)
    for (int c = 0; c < 3; ++c) {
      float expect = std::clamp(a.rgba[i * 4 + c], 0.0f, 1.0f);
      EXPECT_NEAR(b.rgba[i * 4 + c], expect, 0.5f / 65535.0f + 1e-7f);
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
