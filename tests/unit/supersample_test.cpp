// Supersampling in the external renderers (common/supersample.h): the box
// filter's formula, the n-times grid and its size checks, the exports'
// resolution at render.spp = 16, and the POV-Ray harness filtering what a
// stand-in povray wrote. The reference renderer's own spp n^2 render equals
// the box filter of its 1 spp render at n times the resolution: the
// equivalence the external paths rely on.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/temp_files.h"
#include "common/supersample.h"
#include "gltf/gltf_exporter.h"
#include "povray/pov_exporter.h"
#include "povray/pov_render.h"
#include "render/renderer.h"
#include "scene_file/scene_loader.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

fs::path freshDir(const std::string& name) { return test::freshTempDir("xval_ss_" + name); }

std::string slurp(const fs::path& f) { return test::fileText(f); }

Scene sphereScene(int side, int spp) {
  Scene s;
  s.name = "ss";
  s.camera.width = s.camera.height = side;
  s.objects = {UvSphere{}};
  s.render.spp = spp;
  return s;
}

std::string exportErrorOf(const Scene& s) {
  try {
    subpixelGrid(s);
  } catch (const ExportError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

// 4 x 2 samples, n = 2: two pixels. Values above 1 and below 0 show that
// each sample is saturated before the mean (saturating the mean instead
// gives (1.5 + 0.1) / 2 -> 0.8, not 0.55), alpha is the mean coverage and
// raw the unsaturated mean.
TEST(Supersample, BoxFilterSaturatesEachSampleThenAverages) {
  Image fine(4, 2, false);
  fine.raw.assign(4 * 2 * 3, 0.0f);
  // pixel 0: samples (0,0) (1,0) (0,1) (1,1); pixel 1: (2..3, 0..1)
  const float r[8] = {1.5f, 0.1f, 0.2f, 0.3f,  //  row 0
                      -0.5f, 0.0f, 0.4f, 2.0f};  // row 1
  const float a[8] = {1, 1, 1, 1, 1, 0, 1, 1};
  for (int k = 0; k < 8; ++k) {
    fine.rgba[k * 4 + 0] = r[k];
    fine.rgba[k * 4 + 1] = 0.25f;
    fine.rgba[k * 4 + 2] = a[k] ? 0.5f : 0.0f;  // background samples are 0
    fine.rgba[k * 4 + 3] = a[k];
    fine.raw[k * 3 + 0] = r[k];
  }
  const Image out = boxFilter(fine, 2);
  ASSERT_EQ(out.width, 2);
  ASSERT_EQ(out.height, 1);
  EXPECT_FLOAT_EQ(out.rgba[0], (1.0f + 0.1f + 0.0f + 0.0f) / 4);  // 1.5 -> 1, -0.5 -> 0
  EXPECT_FLOAT_EQ(out.rgba[1], 0.25f * 4 / 4);
  EXPECT_FLOAT_EQ(out.rgba[2], 0.5f * 3 / 4);  // one background sample
  EXPECT_FLOAT_EQ(out.rgba[3], 3.0f / 4);      // coverage
  EXPECT_FLOAT_EQ(out.rgba[4], (0.2f + 0.3f + 0.4f + 1.0f) / 4);  // 2.0 -> 1
  EXPECT_FLOAT_EQ(out.rgba[7], 1.0f);
  ASSERT_EQ(out.raw.size(), 2u * 3);
  EXPECT_FLOAT_EQ(out.raw[0], (1.5f + 0.1f - 0.5f + 0.0f) / 4);
  EXPECT_FLOAT_EQ(out.raw[3], (0.2f + 0.3f + 0.4f + 2.0f) / 4);
}

TEST(Supersample, BoxFilterOfOneSampleOnlySaturates) {
  Image fine(2, 1, false);
  fine.rgba = {1.25f, 0.5f, -1.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  const Image out = boxFilter(fine, 1);
  EXPECT_EQ(out.rgba, (std::vector<float>{1.0f, 0.5f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f}));
  EXPECT_TRUE(out.raw.empty());
  EXPECT_THROW(boxFilter(Image(6, 4, false), 4), std::invalid_argument);  // 6 is not a multiple of 4
  EXPECT_THROW(boxFilter(Image(4, 4, false), 0), std::invalid_argument);
}

// The reference renderer at spp n^2 is the box filter of its own 1 spp
// render at n W x n H: the sub-pixel centres (i + (sx + 0.5)/n) are the
// fine pixels' centres. Within float rounding of the ray directions.
TEST(Supersample, ReferenceAtSppIsTheBoxFilterOfTheFineImage) {
  for (int n : {2, 4}) {
    Scene coarse = sphereScene(24, n * n);
    coarse.lights = {PointLight{{-1.5, 1.2, 2.0}, glm::dvec3(1.6), {}}};
    Scene fine = coarse;
    fine.camera.width = fine.camera.height = 24 * n;
    fine.render.spp = 1;
    RenderOptions o = defaultOptions(coarse);
    o.diagnostics = false;
    const Image want = renderScene(coarse, o);
    o.spp = 1;
    const Image got = boxFilter(renderScene(fine, o), n);
    ASSERT_EQ(got.width, want.width);
    double worst = 0;
    int partial = 0;
    for (size_t i = 0; i < want.rgba.size(); ++i) {
      worst = std::max(worst, double(std::abs(got.rgba[i] - want.rgba[i])));
      if (i % 4 == 3 && want.rgba[i] > 0 && want.rgba[i] < 1) ++partial;
    }
    EXPECT_LT(worst, 1e-6) << "n = " << n;
    EXPECT_GT(partial, 10) << "the silhouette must cross pixels for the test to mean anything";
  }
}

TEST(Supersample, GridIsNTimesTheCameraForEverySquareSpp) {
  for (int n = 1; n * n <= kMaxSpp; ++n) {
    Scene s = sphereScene(10, n * n);
    s.camera.height = 7;
    const SubpixelGrid g = subpixelGrid(s);
    EXPECT_EQ(g.n, n);
    EXPECT_EQ(g.width, 10 * n);
    EXPECT_EQ(g.height, 7 * n);
  }
}

TEST(Supersample, GridRefusesWhatTheFormatOrTheImageLimitsDoNotAllow) {
  std::string e = exportErrorOf(sphereScene(16, 8));
  EXPECT_NE(e.find("render.spp = 8"), std::string::npos) << e;
  EXPECT_NE(e.find("perfect square"), std::string::npos) << e;
  e = exportErrorOf(sphereScene(16, 289));  // 17^2, beyond the format's 256
  EXPECT_NE(e.find("render.spp = 289"), std::string::npos) << e;
  EXPECT_NE(e.find("256"), std::string::npos) << e;
  e = exportErrorOf(sphereScene(8192, 4));  // 16384 a side: too many pixels
  EXPECT_NE(e.find("render.spp = 4"), std::string::npos) << e;
  EXPECT_NE(e.find("16384x16384"), std::string::npos) << e;
  e = exportErrorOf(sphereScene(2048, 16));  // 8192 a side: 64 Mi pixels, 8 GiB estimated
  EXPECT_NE(e.find("MiB"), std::string::npos) << e;
  EXPECT_NE(e.find("8192x8192"), std::string::npos) << e;
  EXPECT_EQ(exportErrorOf(sphereScene(1024, 16)), "(no error)");
}

// What POV-Ray is asked for at spp 16: 4 W x 4 H, antialiasing off, and
// the very camera of the spp 1 export.
TEST(Supersample, PovExportAtSpp16Renders4TimesTheResolution) {
  Scene s = sphereScene(20, 16);
  s.camera.height = 12;
  const fs::path d16 = freshDir("pov16"), d1 = freshDir("pov1");
  const PovExport ex = exportPov(s, d16);
  const std::string ini = slurp(ex.ini);
  EXPECT_NE(ini.find("\nWidth=80\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("\nHeight=48\n"), std::string::npos) << ini;
  EXPECT_NE(ini.find("\nAntialias=Off\n"), std::string::npos) << ini;
  EXPECT_NE(slurp(d16 / "README.txt").find("+W80 +H48"), std::string::npos);
  EXPECT_EQ(ex.grid.n, 4);
  s.render.spp = 1;
  exportPov(s, d1);
  EXPECT_EQ(slurp(ex.pov), slurp(d1 / "scene.pov"));  // the camera does not change
  EXPECT_NE(slurp(d1 / "scene.ini").find("\nWidth=20\nHeight=12\n"), std::string::npos);
  s.render.spp = 8;
  EXPECT_THROW(exportPov(s, freshDir("pov8")), ExportError);
}

// What Blender is asked for at spp 16 (the glTF's xval_render extras) and
// the camera it imports (aspect W/H, unchanged).
TEST(Supersample, GltfExportAtSpp16Renders4TimesTheResolution) {
  Scene s = sphereScene(20, 16);
  s.camera.height = 12;
  const GltfExport ex = exportGltf(s, freshDir("gltf16"));
  const nlohmann::json doc = nlohmann::json::parse(slurp(ex.gltf));
  const nlohmann::json r = nlohmann::json::parse(doc["scenes"][0]["extras"]["xval_render"].get<std::string>());
  EXPECT_EQ(r["width"], 80);
  EXPECT_EQ(r["height"], 48);
  EXPECT_EQ(r["subpixels_per_side"], 4);
  EXPECT_DOUBLE_EQ(doc["cameras"][0]["perspective"]["aspectRatio"].get<double>(), 20.0 / 12.0);
}

// A stand-in povray that copies a prepared image to the Output_File_Name
// of scene.ini: the harness reads the 4 W x 4 H image and returns its box
// filter; an image of the scene's own size is an error.
class FakePovray : public ::testing::Test {
 protected:
  void SetUp() override {
    bin_ = freshDir("fakebin");
    old_path_ = std::getenv("PATH") ? std::getenv("PATH") : "";
    setenv("PATH", (bin_.string() + ":/usr/bin:/bin").c_str(), 1);
  }
  void TearDown() override { setenv("PATH", old_path_.c_str(), 1); }
  void installCopying(const fs::path& image) {
    fs::path p = bin_ / "povray";
    std::ofstream(p) << "#!/bin/sh\nout=$(sed -n 's/^Output_File_Name=//p' scene.ini)\nfor a in \"$@\"; do o=$(echo \"$a\" | /bin/sed -n 's/^+O//p'); [ -z \"$o\" ] || out=$o; done\ncp '" << image.string()
                     << "' \"$out\"\n";
    fs::permissions(p, fs::perms::owner_all);
  }
  fs::path bin_;
  std::string old_path_;
};

TEST_F(FakePovray, HarnessBoxFiltersTheSubpixelImage) {
  const fs::path d = freshDir("fakepov");
  Image fine(32, 32, false);
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      float* p = fine.pixel(i, j);
      p[0] = float((i * 7 + j * 3) % 11) / 10.0f;
      p[1] = float(i) / 31.0f;
      p[2] = float(j) / 31.0f;
      p[3] = 1.0f;
    }
  writeImage(fine, d / "fine.png");  // 16-bit codes, no alpha: read back as covered
  const Image want = boxFilter(readImage(d / "fine.png"), 4);
  installCopying(d / "fine.png");
  const Image got = renderWithPovray("povray", sphereScene(8, 16), d / "work", 30.0);
  ASSERT_EQ(got.width, 8);
  ASSERT_EQ(got.height, 8);
  EXPECT_EQ(got.rgba, want.rgba);
  try {
    renderWithPovray("povray", sphereScene(32, 1), d / "work1", 30.0);  // 32 x 32 is right at spp 1
    renderWithPovray("povray", sphereScene(32, 4), d / "work4", 30.0);  // but not at spp 4 (64 x 64)
    FAIL() << "an image of the wrong size was accepted";
  } catch (const ExternalToolError& e) {
    EXPECT_NE(std::string(e.what()).find("64x64"), std::string::npos) << e.what();
  }
}
