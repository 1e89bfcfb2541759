// validate's image handoff (validate/validation/image_handoff.h): a job's
// EXR as read back goes to its case's compare once, and only while the
// file is still the one written.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image/image.h"
#include "support/temp_files.h"
#include "validate/validation/image_handoff.h"

namespace fs = std::filesystem;
using namespace xval;
using xval::validation::ImageHandoff;

namespace {

fs::path dir() {
  static const fs::path d = test::freshTempDir("xval_image_handoff");
  return d;
}

Image sample(float base) {
  Image img(6, 4, true);
  for (size_t i = 0; i < img.rgba.size(); ++i) img.rgba[i] = base + float(i) / 97.0f;
  for (size_t i = 0; i < img.depth.size(); ++i) img.depth[i] = 1.0f + float(i);
  return img;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

void expectSameImage(const Image& a, const Image& b) {
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.has_alpha, b.has_alpha);
  EXPECT_TRUE(sameBits(a.rgba, b.rgba));
  EXPECT_TRUE(sameBits(a.raw, b.raw));
  EXPECT_TRUE(sameBits(a.depth, b.depth));
  EXPECT_TRUE(sameBits(a.backfacing, b.backfacing));
  EXPECT_TRUE(sameBits(a.incidence, b.incidence));
  EXPECT_TRUE(sameBits(a.albedo, b.albedo));
  EXPECT_TRUE(sameBits(a.texel_edge, b.texel_edge));
  EXPECT_TRUE(sameBits(a.triangle_edge, b.triangle_edge));
}

}  // namespace

// What writeImage hands back is what reading the file gives, not the image
// it was given: an image with a texel_edge channel but no depth writes no
// texel_edge (image.h), and neither the read-back nor readImage has one.
TEST(ImageHandoff, TheReadBackIsWhatReadingTheFileGives) {
  Image a(6, 4, false);
  for (size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = float(i) * 0.01f;
  a.texel_edge.assign(24, 3.0f);
  Image back;
  writeImage(a, dir() / "partial.exr", kRenderExrCompression, &back);
  EXPECT_TRUE(back.texel_edge.empty());
  expectSameImage(back, readImage(dir() / "partial.exr"));
  const Image full = sample(0.25f);
  writeImage(full, dir() / "full.exr", kRenderExrCompression, &back);
  expectSameImage(back, readImage(dir() / "full.exr"));
}

TEST(ImageHandoff, AnImageIsHandedOverOnce) {
  ImageHandoff h;
  Image back;
  writeImage(sample(0.5f), dir() / "once.exr", kRenderExrCompression, &back);
  h.put(dir() / "once.exr", back);
  EXPECT_GT(h.bytes(), 0u);
  const std::optional<Image> got = h.take(dir() / "once.exr");
  ASSERT_TRUE(got);
  expectSameImage(*got, readImage(dir() / "once.exr"));
  EXPECT_EQ(h.bytes(), 0u);
  EXPECT_FALSE(h.take(dir() / "once.exr"));
  EXPECT_FALSE(h.take(dir() / "never_put.exr"));
}

// A file written again (same size, other pixels), or only touched, after
// the put is no longer the one written: the compare must read it.
TEST(ImageHandoff, AFileChangedSinceItWasWrittenIsNotHandedOver) {
  ImageHandoff h;
  Image back;
  writeImage(sample(0.5f), dir() / "rewritten.exr", kRenderExrCompression, &back);
  h.put(dir() / "rewritten.exr", back);
  writeImage(sample(0.75f), dir() / "rewritten.exr");
  EXPECT_FALSE(h.take(dir() / "rewritten.exr"));

  writeImage(sample(0.5f), dir() / "touched.exr", kRenderExrCompression, &back);
  h.put(dir() / "touched.exr", back);
  const fs::file_time_type t = fs::last_write_time(dir() / "touched.exr");
  fs::last_write_time(dir() / "touched.exr", t + std::chrono::seconds(1));
  EXPECT_FALSE(h.take(dir() / "touched.exr"));

  writeImage(sample(0.5f), dir() / "removed.exr", kRenderExrCompression, &back);
  h.put(dir() / "removed.exr", back);
  fs::remove(dir() / "removed.exr");
  EXPECT_FALSE(h.take(dir() / "removed.exr"));
  EXPECT_EQ(h.bytes(), 0u);
}

// Beyond max_bytes an image is not kept (its case reads the file).
TEST(ImageHandoff, AnImageOverTheLimitIsNotKept) {
  Image back;
  writeImage(sample(0.5f), dir() / "big.exr", kRenderExrCompression, &back);
  size_t floats = back.rgba.size() + back.raw.size() + back.depth.size() + back.backfacing.size() +
                  back.incidence.size() + back.albedo.size() + back.texel_edge.size() + back.triangle_edge.size();
  for (const DiagnosticsChannel& c : kProbeChannels) floats += (back.*c.member).size();
  const size_t one = floats * sizeof(float);
  ImageHandoff h(one + one / 2);
  writeImage(sample(0.5f), dir() / "big2.exr", kRenderExrCompression, &back);
  h.put(dir() / "big.exr", readImage(dir() / "big.exr"));
  h.put(dir() / "big2.exr", back);
  EXPECT_EQ(h.bytes(), one);
  EXPECT_TRUE(h.take(dir() / "big.exr"));
  EXPECT_FALSE(h.take(dir() / "big2.exr"));
}
