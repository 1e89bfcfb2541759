// The Blender-import check (blender/model_import.h) can fail: Blender's
// import of the original model file agrees with our loader's triangles,
// and the same Blender passes DISAGREE with the reference's passes of a
// deliberately wrong loader (the loaded model changed in memory the way a
// loader defect would change it: a v flip, a wrong node transform, a
// skipped primitive). Also: a model file whose name is Python passes as
// data; a failing or hanging Blender is an error, never a pass; and in
// `xval validate`, the same defects fail the case through its geometry
// check (BlenderImportValidate).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "blender/blender_render.h"
#include "blender/model_import.h"
#include "geometry/model_file.h"
#include "render/geometry_passes.h"
#include "scene_file/scene_loader.h"
#include "support/temp_files.h"
#include "validate/geometry_check.h"
#include "validate/report/junit_report.h"
#include "validate/validation/compare_step.h"
#include "validate/validation/plan.h"
#include "validate/validation/run_job.h"

using namespace xval;
namespace fs = std::filesystem;

namespace {

Scene referenceScene(const std::string& name) {
  return loadScene((fs::path(XVAL_REFERENCE_DIR) / "scenes" / (name + ".json")).string());
}

// The scene with object k's model replaced by `change` applied to a copy
// (what a loader with that defect would have loaded).
template <class F>
Scene withModel(const Scene& s, size_t k, F change) {
  Scene out = s;
  auto& mf = std::get<MeshFile>(out.objects[k].shape);
  Model m = *mf.model;
  change(m);
  mf.model = std::make_shared<const Model>(std::move(m));
  return out;
}

validation::GeometryMetrics againstBlender(const Scene& loader_view, const GeometryPasses& blender) {
  return validation::compareGeometry(referenceGeometryPasses(loader_view), blender);
}

}  // namespace

TEST(BlenderImportCross, WrongLoaderFailsWhereTheRightOnePasses) {
  const fs::path dir = test::freshTempDir("xval_cross_blender_import");
  // BoxTextured's root node turns the box by -90 degrees about x; the box
  // looks the same either way, only its uvs tell.
  const Scene box = referenceScene("mesh_boxtextured_gltf");
  fs::create_directories(dir / "box");
  const GeometryPasses blender = renderModelImport("blender-import", box, dir / "box", 600.0);
  const auto right = againstBlender(box, blender);
  EXPECT_TRUE(right.pass) << validation::toJson(right, validation::kGeometryTolerance);
  EXPECT_GT(right.uv_compared, 10000);

  // A v left running up (the per-format flip forgotten).
  const auto vflip = againstBlender(withModel(box, 0, [](Model& m) {
    for (auto& p : m.primitives)
      for (auto& uv : p.mesh.uvs) uv.y = 1.0 - uv.y;
  }), blender);
  EXPECT_FALSE(vflip.pass);
  EXPECT_GT(vflip.max_uv, 0.1);

  // The node transform skipped: the box's -90 degree turn about x undone,
  // (x, y, z) -> (x, -z, y) on the loaded positions.
  const auto no_node = againstBlender(withModel(box, 0, [](Model& m) {
    for (auto& p : m.primitives)
      for (auto& q : p.mesh.positions) q = {q.x, -q.z, q.y};
  }), blender);
  EXPECT_FALSE(no_node.pass);

  // A declared transform that the Blender side does not see: 1 degree
  // about y on our side only.
  Scene turned = box;
  turned.objects[0].transform.rotate = {{0.0, 1.0, 0.0}, 1.0};
  const auto moved = againstBlender(turned, blender);
  EXPECT_FALSE(moved.pass);
  EXPECT_GT(moved.mask_off, 0);
}

TEST(BlenderImportCross, SkippedPrimitiveFails) {
  const fs::path dir = test::freshTempDir("xval_cross_blender_import_spider");
  const Scene spider = loadScene((fs::path(XVAL_REFERENCE_DIR) / "scenes/mesh_spider_obj.json").string());
  fs::create_directories(dir / "spider");
  const GeometryPasses blender = renderModelImport("blender-import", spider, dir / "spider", 600.0);
  const auto right = againstBlender(spider, blender);
  EXPECT_TRUE(right.pass) << validation::toJson(right, validation::kGeometryTolerance);
  // The spider's largest primitive (by triangles) left out, as a loader
  // that skips one would.
  const auto& prims = std::get<MeshFile>(spider.objects[0].shape).model->primitives;
  ASSERT_GT(prims.size(), 1u);
  size_t largest = 0;
  for (size_t k = 0; k < prims.size(); ++k)
    if (prims[k].mesh.triangleCount() > prims[largest].mesh.triangleCount()) largest = k;
  const auto skipped = againstBlender(withModel(spider, 0, [&](Model& m) {
    m.primitives.erase(m.primitives.begin() + long(largest));
  }), blender);
  EXPECT_FALSE(skipped.pass) << prims[largest].label << " skipped";
  EXPECT_GT(skipped.mask_off - skipped.mask_off_silhouette, 100) << prims[largest].label << " skipped";
}

TEST(BlenderImportCross, ModelFileNamedWithPythonIsData) {
  const fs::path dir = test::freshTempDir("xval_cross_blender_import_hostile");
  const std::string evil = "q'\"); import os; os._exit(3) #\n{x}.ply";
  fs::copy_file(fs::path(XVAL_REFERENCE_DIR) / "models/Wuson.ply", dir / evil);
  nlohmann::json j = nlohmann::json::parse(
      std::ifstream(fs::path(XVAL_REFERENCE_DIR) / "scenes/mesh_wuson_ply.json"));
  j["objects"][0]["path"] = evil;
  j.erase("tolerances");
  const Scene s = parseScene(j.dump(), dir / "scene.json");
  fs::create_directories(dir / "work");
  const auto m = againstBlender(s, renderModelImport("blender-import", s, dir / "work", 600.0));
  EXPECT_TRUE(m.pass) << validation::toJson(m, validation::kGeometryTolerance);
  EXPECT_GT(m.covered, 10000);
}

TEST(BlenderImportCross, BackslashInWorkFolderIsRefused) {
  // Blender reads '\\' as a folder separator (Assimp refuses such a model
  // path already: the loader never loads one).
  const fs::path dir = test::freshTempDir("xval_cross_blender_import_backslash");
  fs::create_directories(dir / "a\\b");
  try {
    renderModelImport("blender-import", referenceScene("mesh_wuson_stl"), dir / "a\\b", 600.0);
    ADD_FAILURE() << "no error";
  } catch (const ExportError& e) {
    EXPECT_NE(std::string(e.what()).find("folder separator"), std::string::npos) << e.what();
  }
}

namespace {
// A fake harness folder: render_gltf.py (only its folder is used) and an
// import_model.py of the given body; XVAL_BLENDER_SCRIPT points at it for
// the test's duration.
struct FakeScript {
  explicit FakeScript(const fs::path& dir, const std::string& body) {
    fs::create_directories(dir);
    std::ofstream(dir / "render_gltf.py") << "\n";
    std::ofstream(dir / "import_model.py") << body;
    const char* old = std::getenv("XVAL_BLENDER_SCRIPT");
    had_ = old != nullptr;
    if (old) old_ = old;
    setenv("XVAL_BLENDER_SCRIPT", (dir / "render_gltf.py").c_str(), 1);
  }
  ~FakeScript() {
    if (had_) setenv("XVAL_BLENDER_SCRIPT", old_.c_str(), 1);
    else unsetenv("XVAL_BLENDER_SCRIPT");
  }
  bool had_ = false;
  std::string old_;
};

std::string errorOf(const Scene& s, const fs::path& work, double timeout) {
  fs::create_directories(work);
  try {
    renderModelImport("blender-import", s, work, timeout);
  } catch (const ExternalToolError& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(BlenderImportCross, FailingHangingOrSilentBlenderIsAnError) {
  const fs::path dir = test::freshTempDir("xval_cross_blender_import_fake");
  const Scene s = referenceScene("mesh_wuson_stl");
  {
    FakeScript f(dir / "fails", "import sys\nsys.exit(3)\n");
    EXPECT_NE(errorOf(s, dir / "w1", 600.0).find("blender-import"), std::string::npos);
  }
  {
    FakeScript f(dir / "silent", "pass\n");
    EXPECT_NE(errorOf(s, dir / "w2", 600.0).find("wrote no image"), std::string::npos);
  }
  {
    FakeScript f(dir / "hangs", "import time\ntime.sleep(120)\n");
    const std::string e = errorOf(s, dir / "w3", 8.0);
    EXPECT_NE(e.find("timed out"), std::string::npos) << e;
  }
}

// xval validate runs the check as the case's geometry check (validate/
// validation/geometry_checks.h): with renderers reference and
// blender-import, mesh_boxtextured_glb passes as loaded. Then the defects
// above (the v flip, the node turn undone), made in memory as above, are
// put where validate reads our loader's view of the scene: the reference's
// passes its job wrote (OUT/<scene>/blender-import.reference-passes.exr)
// are replaced by the passes of the defective load, and the compare step
// runs again from the plan (as `validate --compare-only` does): the check
// fails, the case fails (exit 1), the report and JUnit say so.
TEST(BlenderImportValidate, LoaderDefectFailsTheCase) {
  const fs::path dir = test::freshTempDir("xval_cross_blender_import_validate");
  const fs::path scene_file = fs::path(XVAL_REFERENCE_DIR) / "scenes/mesh_boxtextured_glb.json";
  const validation::Plan plan =
      validation::makePlan({scene_file.string()}, (fs::path(XVAL_REFERENCE_DIR) / "tolerances.json").string(),
                           dir / "out", 600.0, Budget{}, {"reference", "blender-import"});
  validation::writePlan(plan);
  ASSERT_EQ(plan.jobs.size(), 2u);
  ASSERT_EQ(plan.jobs[1].renderer, "blender-import");
  for (const auto& rec : validation::runJobs(plan, validation::jobsToRun(plan, false), {}))
    ASSERT_TRUE(rec.error.empty() && rec.not_expressible.empty()) << rec.error << rec.not_expressible;
  auto results = [&] { return nlohmann::json::parse(std::ifstream(plan.dir / "results.json")); };
  auto report = [&] {
    std::ifstream in(plan.dir / "report.html");
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  const std::string name = "reference-blender-import (geometry)";

  ASSERT_EQ(validation::compareAndReport(plan), 0);
  {
    const nlohmann::json r = results();
    const nlohmann::json& c = r["cases"][0];
    ASSERT_EQ(c["geometry_checks"].size(), 1u) << c.dump(2);
    EXPECT_EQ(c["geometry_checks"][0]["verdict"], "pass") << c["geometry_checks"].dump(2);
    EXPECT_GT(c["geometry_checks"][0]["metrics"]["uv_compared"].get<long long>(), 10000);
    EXPECT_TRUE(c["pass"].get<bool>());
    EXPECT_EQ(c["pairs"].size(), 0u);  // a check is no image pair
    const std::string xml = junitXml(xval::results::readResults(plan.dir / "results.json"), "t");
    EXPECT_NE(xml.find("tests=\"1\" failures=\"0\" errors=\"0\" skipped=\"0\""), std::string::npos) << xml;
    EXPECT_NE(xml.find("name=\"" + name + "\""), std::string::npos) << xml;
  }

  const Scene box = loadScene(scene_file.string());
  const std::vector<std::pair<std::string, Scene>> defects = {
      {"v flipped", withModel(box, 0, [](Model& m) {
         for (auto& p : m.primitives)
           for (auto& uv : p.mesh.uvs) uv.y = 1.0 - uv.y;
       })},
      {"node turn undone", withModel(box, 0, [](Model& m) {
         for (auto& p : m.primitives)
           for (auto& q : p.mesh.positions) q = {q.x, -q.z, q.y};
       })}};
  for (const auto& [what, loaded] : defects) {
    writeImage(toImage(referenceGeometryPasses(loaded)), plan.dir / plan.jobs[1].reference_passes());
    EXPECT_EQ(validation::compareAndReport(plan), 1) << what;
    const nlohmann::json r = results();
    const nlohmann::json& c = r["cases"][0];
    EXPECT_FALSE(c["pass"].get<bool>()) << what;
    EXPECT_EQ(c["geometry_checks"][0]["verdict"], "fail") << what << ": " << c["geometry_checks"].dump(2);
    EXPECT_NE(c["geometry_checks"][0].value("reason", "").find("uv error"), std::string::npos) << what;
    EXPECT_NE(c["attribution"].get<std::string>().find("disagree in geometry"), std::string::npos) << what;
    const std::string html = report();
    EXPECT_NE(html.find("<span class=\"fail\">1 fail</span>, <span class=\"err\">0 errors</span>"), std::string::npos)
        << what;
    EXPECT_NE(html.find("<td class=\"l\">" + htmlEscape(name) + "</td><td class=\"l fail\">FAIL"), std::string::npos)
        << what;
    const std::string xml = junitXml(xval::results::readResults(plan.dir / "results.json"), "t");
    EXPECT_NE(xml.find("tests=\"1\" failures=\"1\""), std::string::npos) << what << xml;
    EXPECT_NE(xml.find("geometry outside its bounds: uv error"), std::string::npos) << what << xml;
  }
}

// In validate, a Blender import that fails is the check's error (exit 2),
// never a pass or a not-expressible; so are the reference's passes gone
// from the job's folder.
TEST(BlenderImportValidate, FailingImportOrMissingPassesIsAnError) {
  const fs::path dir = test::freshTempDir("xval_cross_blender_import_validate_error");
  const fs::path scene_file = fs::path(XVAL_REFERENCE_DIR) / "scenes/mesh_wuson_stl.json";
  const validation::Plan plan =
      validation::makePlan({scene_file.string()}, (fs::path(XVAL_REFERENCE_DIR) / "tolerances.json").string(),
                           dir / "out", 600.0, Budget{}, {"reference", "blender-import"});
  validation::writePlan(plan);
  ASSERT_EQ(plan.jobs.size(), 2u);
  auto check = [&] {
    const nlohmann::json r = nlohmann::json::parse(std::ifstream(plan.dir / "results.json"));
    EXPECT_FALSE(r["cases"][0]["pass"].get<bool>());
    return r["cases"][0]["geometry_checks"][0];
  };
  {
    FakeScript f(dir / "fails", "import sys\nsys.exit(3)\n");
    const auto recs = validation::runJobs(plan, validation::jobsToRun(plan, false), {});
    EXPECT_FALSE(recs[1].error.empty());
  }
  EXPECT_EQ(validation::compareAndReport(plan), 2);
  {
    const nlohmann::json g = check();
    EXPECT_EQ(g["verdict"], "error") << g.dump(2);
    EXPECT_NE(g.value("reason", "").find("blender-import"), std::string::npos) << g.dump(2);
  }
  // The real script: the check passes; then without the reference's passes
  // the compare step cannot compare: an error naming the file.
  validation::runJobs(plan, {1}, {});
  EXPECT_EQ(validation::compareAndReport(plan), 0);
  fs::remove(plan.dir / plan.jobs[1].reference_passes());
  EXPECT_EQ(validation::compareAndReport(plan), 2);
  const nlohmann::json g = check();
  EXPECT_EQ(g["verdict"], "error") << g.dump(2);
  EXPECT_NE(g.value("reason", "").find("reference-passes.exr"), std::string::npos) << g.dump(2);
}
