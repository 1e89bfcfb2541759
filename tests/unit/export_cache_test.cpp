// The export cache (renderers/export_cache.h): a stored export is restored
// byte for byte without exporting; any change of the inputs is a new key;
// a partial, altered or planted entry is never used but exported again.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "files/atomic_write.h"
#include "renderers/export_cache.h"
#include "scene_file/scene_loader.h"
#include "validate/validation/plan.h"

namespace fs = std::filesystem;
using namespace xval;
using namespace xval::renderers;

namespace {

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

struct ExportCacheTest : ::testing::Test {
  fs::path root = fs::temp_directory_path() / ("xval-export-cache-test-" + std::to_string(::getpid()) + "-" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  ExportCache cache{root / "cache"};
  int exports = 0;
  // A stand-in exporter: two files, counted.
  std::function<void(const fs::path&)> write = [this](const fs::path& dir) {
    ++exports;
    fs::create_directories(dir);
    writeFileAtomically(dir / "scene.pov", "scene text " + std::to_string(42));
    writeFileAtomically(dir / "texture.png", std::string(1000, 'x'));
  };
  void SetUp() override { fs::remove_all(root); }
  void TearDown() override { fs::remove_all(root); }
  // An export into a fresh folder through the cache; the folder.
  fs::path run(const std::string& key, const std::string& name) {
    const fs::path dir = root / name;
    fs::create_directories(dir);
    exportThroughCache(cache, "pov", key, dir, write);
    return dir;
  }
};

TEST_F(ExportCacheTest, SecondExportIsRestoredWithoutExporting) {
  const std::string key = exportKey("pov", "inputs-a");
  const fs::path a = run(key, "a");
  EXPECT_EQ(exports, 1);
  const fs::path b = run(key, "b");
  EXPECT_EQ(exports, 1) << "the second export of the same key must come from the cache";
  for (const char* f : {"scene.pov", "texture.png"}) EXPECT_EQ(slurp(a / f), slurp(b / f)) << f;
  EXPECT_FALSE(fs::exists(b / "manifest.json"));
  // Another key (other inputs) is exported.
  run(exportKey("pov", "inputs-b"), "c");
  EXPECT_EQ(exports, 2);
  EXPECT_NE(exportKey("pov", "inputs-a"), exportKey("gltf", "inputs-a"));
}

TEST_F(ExportCacheTest, CorruptEntriesAreExportedAgain) {
  const std::string key = exportKey("pov", "inputs-a");
  run(key, "a");
  const fs::path entry = entryFolder(cache, "pov", key);
  ASSERT_TRUE(fs::is_regular_file(entry / "manifest.json"));
  int expected = 1;
  // Each corruption in turn: the next export is a real one, and whole.
  const std::vector<std::function<void()>> corruptions = {
      [&] { writeFileAtomically(entry / "texture.png", std::string(999, 'x')); },             // truncated
      [&] { writeFileAtomically(entry / "texture.png", std::string(999, 'x') + "y"); },        // same size, altered
      [&] { fs::remove(entry / "manifest.json"); },                                            // interrupted
      [&] { writeFileAtomically(entry / "manifest.json", "{\"format\": "); },                  // garbage
      [&] {                                                                                    // a planted link
        fs::remove(entry / "scene.pov");
        fs::create_symlink("/etc/hostname", entry / "scene.pov");
      },
      [&] {  // a manifest naming a file outside the entry
        std::string m = slurp(entry / "manifest.json");
        const auto at = m.find("\"scene.pov\"");
        ASSERT_NE(at, std::string::npos);
        m.replace(at, 11, "\"../../x\"");
        writeFileAtomically(entry / "manifest.json", m);
      },
  };
  for (size_t k = 0; k < corruptions.size(); ++k) {
    corruptions[k]();
    const fs::path d = run(key, "after" + std::to_string(k));
    EXPECT_EQ(exports, ++expected) << "corruption " << k << " was used instead of exporting again";
    EXPECT_EQ(slurp(d / "texture.png"), std::string(1000, 'x')) << k;
    EXPECT_EQ(slurp(d / "scene.pov"), "scene text 42") << k;
    // Stored again whole: the next one is cached.
    run(key, "again" + std::to_string(k));
    EXPECT_EQ(exports, expected) << k;
  }
  EXPECT_FALSE(fs::exists(root / "x"));
}

TEST_F(ExportCacheTest, AnExportThatFailsStoresNothing) {
  const std::string key = exportKey("pov", "inputs-a");
  auto failing = [](const fs::path& dir) {
    writeFileAtomically(dir / "scene.pov", "half");
    throw ExportError("refused");
  };
  const fs::path dir = root / "a";
  fs::create_directories(dir);
  EXPECT_THROW(exportThroughCache(cache, "pov", key, dir, failing), ExportError);
  EXPECT_FALSE(fs::exists(entryFolder(cache, "pov", key)));
  EXPECT_THROW(entryFolder(cache, "../x", key), std::invalid_argument);
}

TEST_F(ExportCacheTest, SizeIsBounded) {
  cache.max_bytes = 2500;  // two entries of ~1.0 kB fit, three do not
  for (int k = 0; k < 5; ++k) run(exportKey("pov", "inputs-" + std::to_string(k)), "d" + std::to_string(k));
  std::uintmax_t total = 0;
  for (const auto& f : fs::recursive_directory_iterator(cache.dir))
    if (f.is_regular_file()) total += f.file_size();
  EXPECT_LE(total, cache.max_bytes);
  EXPECT_TRUE(fs::exists(entryFolder(cache, "pov", exportKey("pov", "inputs-4"))));  // the newest stays
}

// A store killed before its rename leaves CACHE/.tmp-*; the next store
// removes such a temporary once it is stale, and never a live one.
TEST_F(ExportCacheTest, StaleTemporariesOfKilledStoresAreRemoved) {
  // A store's marker, as a killed store leaves it (the first file it writes).
  run(exportKey("pov", "inputs-0"), "first");
  const fs::path marker = entryFolder(cache, "pov", exportKey("pov", "inputs-0")) / kExportCacheMarker;
  ASSERT_TRUE(fs::is_regular_file(marker));
  // .tmp-mine: the user's, of the same name pattern but without the marker.
  const fs::path stale = cache.dir / ".tmp-killedstore", live = cache.dir / ".tmp-livestore",
                 mine = cache.dir / ".tmp-mine";
  for (const fs::path& t : {stale, live, mine}) {
    fs::create_directories(t);
    if (t != mine) fs::copy_file(marker, t / kExportCacheMarker);
    writeFileAtomically(t / "scene.pov", "half an export");
  }
  const auto now = fs::file_time_type::clock::now();
  fs::last_write_time(stale, now - std::chrono::seconds(kStaleTempSeconds + 60));
  fs::last_write_time(mine, now - std::chrono::seconds(kStaleTempSeconds + 60));
  fs::last_write_time(live, now - std::chrono::seconds(kStaleTempSeconds - 60));
  run(exportKey("pov", "inputs-a"), "a");
  EXPECT_FALSE(fs::exists(stale)) << "a temporary untouched for over kStaleTempSeconds stays";
  EXPECT_TRUE(fs::exists(live / "scene.pov")) << "a temporary written to recently was removed";
  EXPECT_TRUE(fs::exists(mine / "scene.pov")) << "a folder the cache did not mark was removed by its name";
  EXPECT_TRUE(fs::exists(entryFolder(cache, "pov", exportKey("pov", "inputs-a")) / "manifest.json"));
}

// The cache folder may hold the user's own folders and files: whatever
// their size and name (even an entry's), the cache never counts, uses or
// removes what it did not mark.
TEST_F(ExportCacheTest, OnlyWhatTheCacheMarkedIsEverRemoved) {
  cache.max_bytes = 2500;  // two entries of ~1.0 kB fit: pruning runs
  fs::create_directories(cache.dir / "photos");
  fs::create_directories(cache.dir / "notes");
  writeFileAtomically(cache.dir / "photos" / "big.jpg", std::string(10000, 'p'));  // over max_bytes alone
  writeFileAtomically(cache.dir / "notes" / "todo.txt", "mine");
  writeFileAtomically(cache.dir / "loose.txt", std::string(10000, 'l'));
  // A folder of the user's at the name of the entry the next export stores.
  const std::string taken = exportKey("pov", "inputs-taken");
  fs::create_directories(entryFolder(cache, "pov", taken));
  writeFileAtomically(entryFolder(cache, "pov", taken) / "mine.txt", "mine");
  for (int k = 0; k < 4; ++k) run(exportKey("pov", "inputs-" + std::to_string(k)), "d" + std::to_string(k));
  const fs::path d = run(taken, "taken");
  EXPECT_EQ(slurp(d / "scene.pov"), "scene text 42") << "exported without the cache";
  EXPECT_EQ(exports, 5);
  run(taken, "taken-again");
  EXPECT_EQ(exports, 6) << "an entry stored over the user's folder";
  EXPECT_EQ(slurp(cache.dir / "photos" / "big.jpg"), std::string(10000, 'p'));
  EXPECT_EQ(slurp(cache.dir / "notes" / "todo.txt"), "mine");
  EXPECT_EQ(slurp(cache.dir / "loose.txt"), std::string(10000, 'l'));
  EXPECT_EQ(slurp(entryFolder(cache, "pov", taken) / "mine.txt"), "mine");
  EXPECT_FALSE(fs::exists(entryFolder(cache, "pov", taken) / "manifest.json"));
  // The cache's own entries are still bounded.
  std::uintmax_t total = 0;
  for (const auto& e : fs::directory_iterator(cache.dir))
    if (fs::exists(e.path() / kExportCacheMarker))
      for (const auto& f : fs::recursive_directory_iterator(e.path()))
        if (f.is_regular_file()) total += f.file_size();
  EXPECT_LE(total, cache.max_bytes);
}

// The inputs key changes with one byte of the scene file or of a texture.
// A refusal entry holds the exporter's verdict: its messages say
// "refusal" only when it holds one (issue #30: "stored refusal-blender"
// for scenes that were not refused).
TEST_F(ExportCacheTest, RefusalMessagesSayWhetherTheEntryIsARefusal) {
  setExportCache(cache);
  struct Unset {
    ~Unset() { setExportCache({}); }
  } unset;
  auto through = [](const std::string& inputs, const std::string& why) {
    ::testing::internal::CaptureStderr();
    const std::string got = cachedRefusal("blender", inputs, [&] { return why; });
    return std::make_pair(got, ::testing::internal::GetCapturedStderr());
  };
  const auto [none, stored_none] = through("expressible scene", "");
  EXPECT_EQ(none, "");
  EXPECT_NE(stored_none.find("export cache: stored blender's check (no refusal) "), std::string::npos) << stored_none;
  EXPECT_EQ(stored_none.find("refusal-"), std::string::npos) << stored_none;
  const auto [again, cached_none] = through("expressible scene", "must not be asked");
  EXPECT_EQ(again, "");
  EXPECT_NE(cached_none.find("export cache: cached blender's check (no refusal) "), std::string::npos) << cached_none;
  const auto [why, stored_why] = through("refused scene", "a built-in shape");
  EXPECT_EQ(why, "a built-in shape");
  EXPECT_NE(stored_why.find("export cache: stored blender's refusal "), std::string::npos) << stored_why;
  const auto [why2, cached_why] = through("refused scene", "");
  EXPECT_EQ(why2, "a built-in shape");
  EXPECT_NE(cached_why.find("export cache: cached blender's refusal "), std::string::npos) << cached_why;
}

TEST_F(ExportCacheTest, InputsKeyCoversSceneAndTextureBytes) {
  const fs::path src = fs::path(XVAL_REFERENCE_DIR) / "scenes" / "texture16_bilinear_37x23.json";
  const Scene scene = loadScene(src);
  ASSERT_TRUE(scene.material.texture && scene.material.texture->source == TextureSpec::Source::Image);
  // A copy of the scene and its texture in a folder of our own.
  fs::create_directories(root / "scenes");
  const fs::path texture = scene.material.texture->path;
  std::string text = slurp(src);
  const fs::path scene_file = root / "scenes" / "s.json";
  const std::string tex_name = texture.filename().string();
  const auto at = text.find(tex_name);
  ASSERT_NE(at, std::string::npos);
  // The scene names the texture relative to its folder: the same name in ours.
  fs::copy_file(texture, root / "scenes" / tex_name);
  size_t slash = text.rfind('"', at);
  text.replace(slash + 1, at - slash - 1, "");
  writeFileAtomically(scene_file, text);
  auto key = [&] { return validation::exportInputsKey(loadScene(scene_file), scene_file); };
  const std::string k0 = key();
  EXPECT_EQ(key(), k0);
  std::string tex = slurp(root / "scenes" / tex_name);
  tex[tex.size() / 2] = char(tex[tex.size() / 2] ^ 1);
  writeFileAtomically(root / "scenes" / tex_name, tex);
  const std::string k1 = key();
  EXPECT_NE(k1, k0) << "one byte of the texture must change the key";
  writeFileAtomically(scene_file, text + " ");
  EXPECT_NE(key(), k1) << "one byte of the scene file must change the key";
}

}  // namespace
