// The tolerance policy (validate/tolerances.h): the tolerance file, the
// lookup of a scene's declared tolerance per renderer, the derived rule for
// a pair of external renderers, and the rule that finds the tolerance file
// (a temporary folder tree, run from other working directories).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "scene/json_reader.h"
#include "validate/tolerances.h"

namespace xval {
namespace {

namespace fs = std::filesystem;

// A fresh folder for one test, removed afterwards.
struct TempTree {
  fs::path root;
  TempTree() {
    root = fs::temp_directory_path() / ("xval_tolerances_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root);
    fs::create_directories(root);
  }
  ~TempTree() {
    std::error_code ec;
    fs::remove_all(root, ec);
  }
  fs::path write(const fs::path& rel, const std::string& text) const {
    fs::create_directories((root / rel).parent_path());
    std::ofstream(root / rel) << text;
    return root / rel;
  }
};

// Runs the rest of a scope in another working directory.
struct WorkingDirectory {
  fs::path before = fs::current_path();
  explicit WorkingDirectory(const fs::path& dir) { fs::current_path(dir); }
  ~WorkingDirectory() { fs::current_path(before); }
};

std::string toleranceFile(double max16, double fraction) {
  return "{\"default\": {\"max_abs_16bit\": " + std::to_string(max16) + ", \"fraction\": " + std::to_string(fraction) +
         ", \"max_unexplained_16bit\": 64}}";
}

ToleranceTable table(double max16, double fraction) {
  ToleranceTable t;
  t.default_tolerance.max_abs = max16 / 65535.0;
  t.default_tolerance.fraction = fraction;
  t.default_tolerance.max_unexplained = 16.0 / 65535.0;
  return t;
}

DeclaredTolerance declared(std::string renderer, std::optional<double> max16, std::optional<double> fraction,
                           bool exclude_backfacing, std::string reason) {
  DeclaredTolerance d;
  d.renderer = std::move(renderer);
  d.max_abs_16bit = max16, d.fraction = fraction, d.exclude_backfacing = exclude_backfacing;
  d.reason = std::move(reason);
  return d;
}

// --- the file

TEST(LoadTolerances, ReadsTheDefault) {
  TempTree t;
  const fs::path f = t.write("tolerances.json", "{\"description\": \"x\", \"default\": {\"max_abs_16bit\": 3, \"fraction\": 0.99, "
                                         "\"max_unexplained_16bit\": 40}}");
  const ToleranceTable table = loadTolerances(f);
  EXPECT_EQ(table.default_tolerance.max_abs, 3.0 / 65535.0);
  EXPECT_EQ(table.default_tolerance.fraction, 0.99);
  EXPECT_EQ(table.default_tolerance.max_unexplained, 40.0 / 65535.0);
  EXPECT_FALSE(table.default_tolerance.exclude_backfacing);
  EXPECT_EQ(table.source, f);
}

TEST(LoadTolerances, TheToolkitsFileHoldsTheProjectDefault) {
  // 2/65535 on 99.9% of the covered pixels (docs/scene-format.md).
  const ToleranceTable table = loadTolerances(toolkitToleranceFile());
  EXPECT_EQ(table.default_tolerance.max_abs, 2.0 / 65535.0);
  EXPECT_EQ(table.default_tolerance.fraction, 0.999);
  EXPECT_EQ(table.default_tolerance.max_unexplained, 128.0 / 65535.0);  // docs/pixel-classes.md
}

void expectError(const std::string& text, std::initializer_list<std::string> said) {
  TempTree t;
  const fs::path f = t.write("tolerances.json", text);
  try {
    loadTolerances(f);
    FAIL() << "accepted " << text;
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(f.string()), std::string::npos) << what;  // the file
    for (const auto& s : said) EXPECT_NE(what.find(s), std::string::npos) << "no \"" << s << "\" in: " << what;
  }
}

TEST(LoadTolerances, ErrorsNameTheFileTheFieldAndTheValue) {
  expectError("{\"default\": {\"max_abs_16bit\": 2, \"max_abs_16bit\": 3, \"fraction\": 0.9, \"max_unexplained_16bit\": 8}}",
              {"default.max_abs_16bit", "duplicate field"});
  expectError("{\"default\": {\"max_abs_16bit\": 2, \"fraction\": 1.5, \"max_unexplained_16bit\": 8}}", {"default.fraction", "1.5"});
  expectError("{\"default\": {\"max_abs_16bit\": -1, \"fraction\": 0.9, \"max_unexplained_16bit\": 8}}", {"default.max_abs_16bit", "-1"});
  expectError("{\"default\": {\"max_abs_16bit\": 2, \"fraction\": 0.9, \"max\": 4, \"max_unexplained_16bit\": 8}}", {"default.max", "unknown field"});
  expectError("{\"default\": {\"fraction\": 0.9}}", {"default.max_abs_16bit", "required"});
  expectError("{\"default\": {\"max_abs_16bit\": 2, \"fraction\": 0.9}}", {"default.max_unexplained_16bit", "required"});
  expectError("{\"default\": {\"max_abs_16bit\": 2, \"fraction\": 0.9, \"max_unexplained_16bit\": -1}}",
              {"default.max_unexplained_16bit", "-1"});
  expectError("{\"defaults\": {}}", {"default"});
}

// --- lookup

TEST(ToleranceLookup, WithoutADeclarationTheDefault) {
  Scene s;
  s.tolerances.push_back(declared("povray", 4, 0.99, true, "why"));
  std::string reason = "stale";
  const Tolerance t = table(2, 0.999).lookup(s, "blender", &reason);
  EXPECT_EQ(t.max_abs, 2.0 / 65535.0);
  EXPECT_EQ(t.fraction, 0.999);
  EXPECT_FALSE(t.exclude_backfacing);
  EXPECT_EQ(reason, "");
}

TEST(ToleranceLookup, TheScenesDeclarationForThatRendererWithItsReason) {
  Scene s;
  s.tolerances.push_back(declared("blender", 8, std::nullopt, false, "blender's reason"));
  s.tolerances.push_back(declared("povray", 4, 0.995, true, "povray's reason"));
  std::string reason;
  const Tolerance p = table(2, 0.999).lookup(s, "povray", &reason);
  EXPECT_EQ(p.max_abs, 4.0 / 65535.0);
  EXPECT_EQ(p.fraction, 0.995);
  EXPECT_TRUE(p.exclude_backfacing);
  EXPECT_EQ(reason, "povray's reason");
  // A field not declared keeps the default's.
  const Tolerance b = table(2, 0.999).lookup(s, "blender", &reason);
  EXPECT_EQ(b.max_abs, 8.0 / 65535.0);
  EXPECT_EQ(b.fraction, 0.999);
  EXPECT_FALSE(b.exclude_backfacing);
  EXPECT_EQ(reason, "blender's reason");
}

TEST(ToleranceLookup, APairWithTheReferenceUsesTheOtherRenderersTolerance) {
  Scene s;
  s.tolerances.push_back(declared("povray", 4, 0.995, false, "povray's reason"));
  const ToleranceTable tt = table(2, 0.999);
  for (auto [a, b] : {std::pair{"reference", "povray"}, {"povray", "reference"}}) {
    std::string reason;
    const Tolerance t = tt.lookupPair(s, a, b, &reason);
    EXPECT_EQ(t.max_abs, 4.0 / 65535.0) << a << "-" << b;
    EXPECT_EQ(t.fraction, 0.995);
    EXPECT_EQ(reason, "povray's reason");
  }
}

// Two external renderers: the sum of the bounds on f1 + f2 - 1 of the
// pixels (triangle inequality, union bound).
TEST(ToleranceLookup, TheDerivedRuleForTwoExternalRenderers) {
  Scene s;
  s.tolerances.push_back(declared("povray", 4, 0.995, false, "p"));
  s.tolerances.push_back(declared("blender", std::nullopt, 0.998, true, "b"));
  std::string reason;
  const Tolerance t = table(2, 0.999).lookupPair(s, "povray", "blender", &reason);
  EXPECT_EQ(t.max_abs, 4.0 / 65535.0 + 2.0 / 65535.0);
  EXPECT_DOUBLE_EQ(t.fraction, 0.995 + 0.998 - 1.0);
  EXPECT_TRUE(t.exclude_backfacing);  // either leaves back faces out
  EXPECT_EQ(reason.rfind("derived: ", 0), 0u) << reason;
  // The caps on unexplained pixels add up (a declared one replaces the
  // default's 16).
  s.tolerances[0].max_unexplained_16bit = 100;
  EXPECT_EQ(table(2, 0.999).lookup(s, "povray").max_unexplained, 100.0 / 65535.0);
  EXPECT_EQ(table(2, 0.999).lookupPair(s, "povray", "blender").max_unexplained, 116.0 / 65535.0);
  // Fractions that add up to less than 1 give 0, never a negative share.
  Scene loose;
  loose.tolerances.push_back(declared("povray", std::nullopt, 0.3, false, "p"));
  loose.tolerances.push_back(declared("blender", std::nullopt, 0.4, false, "b"));
  EXPECT_EQ(table(2, 0.999).lookupPair(loose, "povray", "blender").fraction, 0.0);
}

// --- which file: the rule

TEST(FindToleranceFile, TheFileGivenFirst) {
  TempTree t;
  const fs::path scene = t.write("set/scenes/x.json", "{}");
  t.write("set/tolerances.json", toleranceFile(2, 0.999));
  const fs::path given = t.write("mine.json", toleranceFile(5, 0.9));
  const ToleranceFile f = findToleranceFile(given, {scene});
  EXPECT_EQ(f.path, given);
  EXPECT_EQ(f.found_by, "given");
  // A relative path given is relative to the working directory.
  WorkingDirectory wd(t.root);
  EXPECT_EQ(findToleranceFile("mine.json", {scene}).path, given);
}

TEST(FindToleranceFile, TheNearestInTheScenesFolderOrAbove) {
  TempTree t;
  const fs::path x = t.write("set/scenes/x.json", "{}"), y = t.write("set/scenes/deep/er/y.json", "{}");
  const fs::path set_file = t.write("set/tolerances.json", toleranceFile(2, 0.999));
  EXPECT_EQ(findToleranceFile({}, {x}).path, set_file);
  EXPECT_EQ(findToleranceFile({}, {x}).found_by, "nearest to the scene");
  EXPECT_EQ(findToleranceFile({}, {x, y}).path, set_file);
  // A nearer one wins.
  const fs::path scenes_file = t.write("set/scenes/tolerances.json", toleranceFile(3, 0.999));
  EXPECT_EQ(findToleranceFile({}, {x}).path, scenes_file);
  EXPECT_EQ(findToleranceFile({}, {y}).path, scenes_file);
}

// Nothing to do with the working directory: the same file from the scene's
// folder, from a sibling folder with a relative scene path, from the root
// and from a folder that has a tolerances.json of its own.
TEST(FindToleranceFile, DoesNotDependOnTheWorkingDirectory) {
  TempTree t;
  const fs::path x = t.write("set/scenes/x.json", "{}");
  const fs::path set_file = t.write("set/tolerances.json", toleranceFile(2, 0.999));
  t.write("elsewhere/tolerances.json", toleranceFile(9, 0.5));
  fs::create_directories(t.root / "sibling");
  for (const auto& [cwd, scene] : {std::pair<fs::path, fs::path>{t.root / "set/scenes", "x.json"},
                                   {t.root / "sibling", "../set/scenes/x.json"},
                                   {"/", x},
                                   {t.root / "elsewhere", x}}) {
    WorkingDirectory wd(cwd);
    const ToleranceFile f = findToleranceFile({}, {scene});
    EXPECT_EQ(f.path, set_file) << "from " << cwd << " with " << scene;
    EXPECT_EQ(loadTolerances(f.path).default_tolerance.max_abs, 2.0 / 65535.0);
  }
}

TEST(FindToleranceFile, ElseTheToolkitsOwn) {
  TempTree t;
  const fs::path z = t.write("loose/z.json", "{}");
  for (fs::path d = t.root; ; d = d.parent_path()) {
    ASSERT_FALSE(fs::exists(d / "tolerances.json")) << "the test needs no tolerances.json above " << t.root;
    if (!d.has_relative_path()) break;
  }
  const ToleranceFile f = findToleranceFile({}, {z});
  EXPECT_EQ(f.path, toolkitToleranceFile());
  EXPECT_EQ(f.found_by, "the toolkit's own");
  // Without a scene (compare, extremes): the toolkit's own too.
  EXPECT_EQ(findToleranceFile({}, {}).path, toolkitToleranceFile());
  // The toolkit's own is this source tree's reference/tolerances.json,
  // wherever the command runs.
  WorkingDirectory wd(t.root);
  EXPECT_EQ(toolkitToleranceFile(), fs::path(XVAL_REFERENCE_DIR "/tolerances.json").lexically_normal());
  EXPECT_TRUE(fs::is_regular_file(toolkitToleranceFile()));
}

TEST(FindToleranceFile, ScenesThatFindDifferentFilesAreRefused) {
  TempTree t;
  const fs::path a = t.write("a/x.json", "{}"), b = t.write("b/y.json", "{}"), c = t.write("c/z.json", "{}");
  t.write("a/tolerances.json", toleranceFile(2, 0.999));
  t.write("b/tolerances.json", toleranceFile(4, 0.999));
  try {
    findToleranceFile({}, {a, b});
    FAIL() << "two sets with different tolerance files were accepted";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    for (const auto& s : {a.string(), b.string(), (t.root / "a/tolerances.json").string(),
                          (t.root / "b/tolerances.json").string(), std::string("--tolerances")})
      EXPECT_NE(what.find(s), std::string::npos) << "no \"" << s << "\" in: " << what;
  }
  // One that finds a file and one that finds none (the toolkit's own).
  EXPECT_THROW(findToleranceFile({}, {a, c}), std::runtime_error);
  // Given, the file is used for all of them.
  EXPECT_EQ(findToleranceFile(t.root / "a/tolerances.json", {a, b, c}).path, t.root / "a/tolerances.json");
}

// The climb stops at the set root: the folder holding `scenes`, else the
// scene's own folder. A tolerances.json above it (in a shared folder such
// as /tmp) is never looked at.
TEST(FindToleranceFile, TheClimbStopsAtTheSetRoot) {
  TempTree t;
  t.write("tolerances.json", toleranceFile(65535, 0));  // planted above every set
  const fs::path loose = t.write("loose/z.json", "{}"), deep = t.write("set/scenes/deep/x.json", "{}");
  EXPECT_EQ(setRootOf(loose), t.root / "loose");
  EXPECT_EQ(setRootOf(deep), t.root / "set");
  EXPECT_EQ(findToleranceFile({}, {loose}).path, toolkitToleranceFile());
  EXPECT_EQ(findToleranceFile({}, {deep}).path, toolkitToleranceFile());
  const fs::path set_file = t.write("set/tolerances.json", toleranceFile(2, 0.999));
  EXPECT_EQ(findToleranceFile({}, {deep}).path, set_file);
  // The toolkit's own layout: reference/scenes/x.json -> reference/tolerances.json.
  EXPECT_EQ(setRootOf(fs::path(XVAL_REFERENCE_DIR) / "scenes" / "light_spot.json"),
            fs::path(XVAL_REFERENCE_DIR).lexically_normal());
}

// A file found (not given) that another user could have written is refused,
// naming the file and why.
void expectRefused(const fs::path& scene, const fs::path& file, const std::string& why) {
  try {
    const ToleranceFile f = findToleranceFile({}, {scene});
    ADD_FAILURE() << "used " << f.path << " although " << why;
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    for (const std::string& s : {file.string(), why, std::string("--tolerances")})
      EXPECT_NE(what.find(s), std::string::npos) << "no \"" << s << "\" in: " << what;
  }
  // Given, the user vouches for it.
  EXPECT_EQ(findToleranceFile(file, {scene}).path, file);
}

TEST(FindToleranceFile, AFileWritableByOthersIsRefused) {
  TempTree t;
  const fs::path x = t.write("set/scenes/x.json", "{}");
  const fs::path f = t.write("set/tolerances.json", toleranceFile(2, 0.999));
  fs::permissions(f, fs::perms::others_write, fs::perm_options::add);
  expectRefused(x, f, "writable by every user (mode 0");
  fs::permissions(f, fs::perms::others_write, fs::perm_options::remove);
  EXPECT_EQ(findToleranceFile({}, {x}).path, f);
  // In a folder anyone may write to (no sticky bit): anyone could replace it.
  fs::permissions(t.root / "set", fs::perms::others_all, fs::perm_options::add);
  expectRefused(x, f, "writable by every user without the sticky bit");
  // With the sticky bit (as /tmp), only its owner can replace it.
  fs::permissions(t.root / "set", fs::perms::sticky_bit, fs::perm_options::add);
  EXPECT_EQ(findToleranceFile({}, {x}).path, f);
}

TEST(FindToleranceFile, AFileOwnedByAnotherUserIsRefused) {
  if (geteuid() != 0) GTEST_SKIP() << "needs root (to give a file to the user nobody); the mode checks run as anyone";
  TempTree t;
  const fs::path x = t.write("set/scenes/x.json", "{}");
  const fs::path f = t.write("set/tolerances.json", toleranceFile(2, 0.999));
  ASSERT_EQ(chown(f.c_str(), 65534, 65534), 0);
  expectRefused(x, f, "owned by uid 65534");
  // The scene's owner may own it (a colleague's set run by another user).
  ASSERT_EQ(chown(x.c_str(), 65534, 65534), 0);
  EXPECT_EQ(findToleranceFile({}, {x}).path, f);
  // A link owned by another user to a trusted file is refused too.
  ASSERT_EQ(chown(x.c_str(), 0, 0), 0);
  ASSERT_EQ(chown(f.c_str(), 0, 0), 0);
  fs::rename(f, t.root / "set/real.json");
  fs::create_symlink("real.json", f);
  ASSERT_EQ(lchown(f.c_str(), 65534, 65534), 0);
  expectRefused(x, f, "a symbolic link owned by uid 65534");
}

}  // namespace
}  // namespace xval
