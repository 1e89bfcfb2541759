// The comparison outputs' names and the removal of stale ones
// (validate/compare_outputs.h): the writers' names are of the kinds the
// removal knows; it removes those not named and nothing else.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/temp_files.h"
#include "validate/compare_outputs.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {
void touch(const fs::path& f) { std::ofstream(f) << "x\n"; }
}  // namespace

TEST(CompareOutputs, EveryNameTheWritersUseIsOfAKind) {
  for (const std::string& n : {diffExrName("reference-povray"), heatMapName("reference-povray"),
                               boundMapName("reference-povray"),
                               cropName("reference-povray", "worst_unexplained", "heat"),
                               cropName("reference-povray", "worst_explained", "povray")})
    EXPECT_TRUE(isCompareOutputName(n)) << n;
  EXPECT_EQ(boundMapName("a-b"), "heat_bound_a-b.png");
  EXPECT_EQ(cropName("a-b", "worst_unexplained", "a"), "crop_a-b_worst_unexplained_a.png");
}

TEST(CompareOutputs, OtherNamesAreNot) {
  for (const char* n : {"reference.exr", "reference.png", "reference.job.json", "heat_.png", "diff_.exr",
                        "heat_x.exr", "diff_x.png", "crop_x.txt", "notes.txt", "heat_scale.png.partial-1",
                        "my_heat_x.png"})
    EXPECT_FALSE(isCompareOutputName(n)) << n;
}

TEST(CompareOutputs, RemovesTheUnnamedOnesAndNothingElse) {
  const fs::path dir = test::freshTempDir("xval_compare_outputs_test");
  const fs::path outside = test::freshTempDir("xval_compare_outputs_outside");
  for (const char* f : {"diff_a-b.exr", "heat_a-b.png", "diff_a-gone.exr", "heat_a-gone.png", "heat_bound_a-gone.png",
                        "crop_a-b_worst_unexplained_a.png", "notes.txt", "a.exr", "a.png"})
    touch(dir / f);
  touch(outside / "crop_target.png");
  fs::create_symlink(outside / "crop_target.png", dir / "crop_link.png");
  fs::create_directory_symlink(outside, dir / "heat_folder.png");
  fs::create_directory(dir / "diff_sub.exr");
  const std::vector<std::string> removed = removeStaleCompareOutputs(dir, {"diff_a-b.exr", "heat_a-b.png"});
  EXPECT_EQ(removed, (std::vector<std::string>{"crop_a-b_worst_unexplained_a.png", "diff_a-gone.exr",
                                               "heat_a-gone.png", "heat_bound_a-gone.png"}));
  for (const char* f : {"diff_a-b.exr", "heat_a-b.png", "notes.txt", "a.exr", "a.png", "diff_sub.exr"})
    EXPECT_TRUE(fs::exists(dir / f)) << f;
  EXPECT_TRUE(fs::is_symlink(dir / "crop_link.png"));
  EXPECT_TRUE(fs::is_symlink(dir / "heat_folder.png"));
  EXPECT_TRUE(fs::exists(outside / "crop_target.png"));
}

TEST(CompareOutputs, AFolderThatCannotBeListedIsAnErrorNamingIt) {
  const fs::path missing = test::freshTempDir("xval_compare_outputs_missing") / "none";
  try {
    removeStaleCompareOutputs(missing, {});
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(missing.string()), std::string::npos) << e.what();
  }
}
