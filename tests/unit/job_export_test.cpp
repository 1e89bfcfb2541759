// A job's refusal and export in one (renderers/job_export.h): the refusal
// of a renderer that exports is decided by the export its render reads,
// written once; through the export cache, a refusal is keyed by the
// renderer's definition file's bytes and a restored export never skips the
// renderer's own check.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <sys/stat.h>

#include "files/atomic_write.h"
#include "renderers/export_cache.h"
#include "renderers/job_export.h"
#include "renderers/renderer_file.h"
#include "scene_file/scene_loader.h"

namespace fs = std::filesystem;
using namespace xval;
using namespace xval::renderers;

namespace {

struct JobExportTest : ::testing::Test {
  fs::path root = fs::temp_directory_path() / ("xval-job-export-test-" + std::to_string(::getpid()) + "-" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  int writes = 0;
  std::string refuse_write;  // the exporter's refusal ("" : none)
  Scene scene;
  void SetUp() override {
    fs::remove_all(root);
    fs::create_directories(root);
  }
  void TearDown() override {
    setExportCache({});
    fs::remove_all(root);
  }
  // A renderer whose exporter writes scene.txt, counted; `refuse_check` is
  // its check's refusal ("" : none).
  Renderer renderer(const std::string& id, const std::string& refuse_check = "") {
    Renderer r;
    r.id = id;
    r.exporter = RendererExport{
        "test",
        [refuse_check](const Scene&) {
          if (!refuse_check.empty()) throw ExportError(refuse_check);
        },
        [this](const Scene&, const fs::path& dir) {
          ++writes;
          if (!refuse_write.empty()) throw ExportError(refuse_write);
          writeFileAtomically(dir / "scene.txt", "exported");
        },
        ""};
    r.cannot_express = [ex = *r.exporter](const Scene& s) { return refusalOf(ex, s); };
    return r;
  }
  // refuseOrExport into a fresh work folder `name`, with `key` as the inputs key.
  RenderRequest job(const Renderer& r, const std::string& name, const std::string& key, std::string* why) {
    RenderRequest request;
    request.work_dir = root / name;
    request.export_key = key;
    fs::create_directories(request.work_dir);
    *why = refuseOrExport(r, scene, request);
    return request;
  }
};

TEST_F(JobExportTest, TheRefusalCheckIsTheExportTheRenderReads) {
  const Renderer r = renderer("fake");
  std::string why;
  const RenderRequest request = job(r, "a", "", &why);
  EXPECT_EQ(why, "");
  EXPECT_EQ(writes, 1) << "a job exports its scene once: the check's export is the render's";
  EXPECT_TRUE(request.exported);
  EXPECT_TRUE(fs::is_regular_file(request.work_dir / "scene.txt"));
  // A refusal: nothing handed on.
  refuse_write = "cannot express X";
  const RenderRequest refused = job(r, "b", "", &why);
  EXPECT_EQ(why, "cannot express X");
  EXPECT_FALSE(refused.exported);
}

TEST_F(JobExportTest, ThroughTheCacheARefusalIsKeyedByTheDefinitionFile) {
  setExportCache({root / "cache"});
  Renderer r = renderer("defined");
  r.definition_file = root / "defined.json";
  writeFileAtomically(r.definition_file, "{\"version\": 1}");
  refuse_write = "refused by version 1";
  std::string why;
  job(r, "a", "inputs", &why);
  EXPECT_EQ(why, "refused by version 1");
  EXPECT_EQ(writes, 1);
  refuse_write = "";
  job(r, "b", "inputs", &why);
  EXPECT_EQ(why, "refused by version 1") << "the same definition and inputs: the stored refusal";
  EXPECT_EQ(writes, 1);
  writeFileAtomically(r.definition_file, "{\"version\": 2}");
  const RenderRequest c = job(r, "c", "inputs", &why);
  EXPECT_EQ(why, "") << "a changed definition file must not read the old refusal back";
  EXPECT_EQ(writes, 2);
  EXPECT_TRUE(c.exported);
  EXPECT_NE(refusalKey(r, "inputs"), refusalKey(renderer("defined"), "inputs"));
}

TEST_F(JobExportTest, ThroughTheCacheAWarmJobWritesNothingAndStillHasItsExport) {
  setExportCache({root / "cache"});
  const Renderer r = renderer("fake");
  std::string why;
  job(r, "a", "inputs", &why);
  EXPECT_EQ(writes, 1);
  const RenderRequest b = job(r, "b", "inputs", &why);
  EXPECT_EQ(why, "");
  EXPECT_EQ(writes, 1) << "the refusal and the export both from the cache";
  EXPECT_TRUE(b.exported);
  EXPECT_TRUE(fs::is_regular_file(b.work_dir / "scene.txt"));
}

TEST_F(JobExportTest, ARestoredExportNeverSkipsTheRenderersOwnCheck) {
  // Two renderers of one exporter (as blender and eevee share the glTF):
  // the second refuses in its check what the first exported.
  setExportCache({root / "cache"});
  std::string why;
  job(renderer("first"), "a", "inputs", &why);
  EXPECT_EQ(why, "");
  const RenderRequest b = job(renderer("second", "second refuses"), "b", "inputs", &why);
  EXPECT_EQ(why, "second refuses");
  EXPECT_FALSE(b.exported);
}

}  // namespace

// A renderer defined by a file (renderers/renderer_file.h) exports once
// too: after refuseOrExport, its render hands the program the very files
// the check wrote (the same inodes: an export writes each file anew, by
// rename), in the documented place <work>/pov.
TEST_F(JobExportTest, ARendererDefinedByAFileRendersTheExportItsCheckWrote) {
  const fs::path def = root / "defined.json";
  writeFileAtomically(def, R"({"format": "xval-renderer/1", "name": "defined-pov", "input": "pov",
    "command": ["true", "{input}", "{output}"], "version_command": ["true"]})");
  const Renderer r = loadRendererFile(def);
  ASSERT_TRUE(r.exporter.has_value());
  const Scene s = loadScene(fs::path(XVAL_REFERENCE_DIR) / "scenes" / "texture16_bilinear_37x23.json");
  RenderRequest request;
  request.work_dir = root / "job";
  fs::create_directories(request.work_dir);
  ASSERT_EQ(refuseOrExport(r, s, request), "");
  ASSERT_TRUE(request.exported);
  const fs::path pov = request.work_dir / "pov" / "scene.pov";
  struct stat before{}, after{};
  ASSERT_EQ(::stat(pov.c_str(), &before), 0) << pov << ": the check's export is not where the render reads it";
  // `true` writes no image: the render fails after handing over its input.
  EXPECT_THROW(r.render(s, request, nullptr), ExternalToolError);
  ASSERT_EQ(::stat(pov.c_str(), &after), 0);
  EXPECT_EQ(before.st_ino, after.st_ino) << "the render exported the scene again";
}
