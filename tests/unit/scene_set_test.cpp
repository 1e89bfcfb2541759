// scene_file/scene_set.h: the scene files of a command's inputs, one rule for
// validate, golden and pack.
#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "scene_file/scene_set.h"
#include "support/temp_files.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

void put(const fs::path& f, const std::string& text) {
  std::ofstream(f) << text;
}

std::string errorOf(const std::vector<std::string>& inputs) {
  try {
    findSceneFiles(inputs);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// A folder: its *.json sorted (not its subfolders' files, nor other
// names); a linked scene is the file it names.
TEST(SceneSet, FolderGivesItsJsonFilesSorted) {
  const fs::path d = test::freshTempDir("scene_set");
  put(d / "b.json", "{}");
  put(d / "a.json", "{}");
  put(d / "notes.txt", "x");
  fs::create_directory(d / "sub");
  put(d / "sub" / "c.json", "{}");
  put(d / "elsewhere.txt", "{}");
  fs::create_symlink(d / "elsewhere.txt", d / "linked.json");
  const SceneFiles found = findSceneFiles({d.string()});
  EXPECT_EQ(found.scenes, (std::vector<fs::path>{d / "a.json", d / "b.json", d / "linked.json"}));
  EXPECT_TRUE(found.skipped.empty());
  EXPECT_EQ(jsonFilesOf({d.string()}), found.scenes);
}

// A tolerance file and another xval format in a folder are skipped with
// the reason; given by name, a file is taken (loading it says what is
// wrong). golden check used to load them as scenes.
TEST(SceneSet, FolderSkipsFilesThatAreNotScenes) {
  const fs::path d = test::freshTempDir("scene_set");
  put(d / "scene.json", "{\"name\": \"x\"}");
  put(d / "tolerances.json", "{}");
  put(d / "spec.json", "{\"format\": \"xval-generate/1\"}");
  const SceneFiles found = findSceneFiles({d.string()});
  EXPECT_EQ(found.scenes, (std::vector<fs::path>{d / "scene.json"}));
  ASSERT_EQ(found.skipped.size(), 2u);
  EXPECT_EQ(found.skipped[0].file, d / "spec.json");
  EXPECT_NE(found.skipped[0].reason.find("xval-generate/1"), std::string::npos) << found.skipped[0].reason;
  EXPECT_EQ(found.skipped[1].file, d / "tolerances.json");
  EXPECT_EQ(found.skipped[1].reason, "a tolerance file");
  EXPECT_EQ(jsonFilesOf({d.string()}).size(), 3u);  // pack packs the skipped ones too
  const SceneFiles given = findSceneFiles({(d / "spec.json").string()});
  EXPECT_EQ(given.scenes, (std::vector<fs::path>{d / "spec.json"}));
}

// What is not a regular file but named *.json stays in, so that loading
// it is an error naming it, not a file passed over in silence.
TEST(SceneSet, FolderKeepsAJsonThatIsNotARegularFile) {
  const fs::path d = test::freshTempDir("scene_set");
  fs::create_directory(d / "folder.json");
  fs::create_symlink(d / "missing", d / "dangling.json");
  EXPECT_EQ(findSceneFiles({d.string()}).scenes, (std::vector<fs::path>{d / "dangling.json", d / "folder.json"}));
}

// Errors name the input: one that is neither file nor folder, and inputs
// with no scene (with what was skipped).
TEST(SceneSet, ErrorsNameTheInput) {
  const fs::path d = test::freshTempDir("scene_set");
  const std::string missing = (d / "nope").string();
  EXPECT_EQ(errorOf({missing}), missing + ": no such scene file or folder");
  fs::create_directory(d / "empty");
  EXPECT_EQ(errorOf({(d / "empty").string()}), "no scene files found in " + (d / "empty").string());
  put(d / "tolerances.json", "{}");
  EXPECT_EQ(errorOf({d.string()}), "no scene files found in " + d.string() + " (skipped: " +
                                        (d / "tolerances.json").string() + ": a tolerance file)");
}
