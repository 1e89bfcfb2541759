// validation::run (validate/validation/validate_run.h): a request decides
// the step; a request that cannot run is refused before anything is
// written, and --plan-only writes the plan and renders nothing.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "support/temp_files.h"
#include "validate/validation/validate_run.h"

using namespace xval;
namespace fs = std::filesystem;
namespace v = xval::validation;

namespace {

std::string errorOf(const v::ValidateRequest& r) {
  try {
    v::run(r);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

const std::string kScene = XVAL_REFERENCE_DIR "/scenes/fig1_phong_behind.json";

}  // namespace

TEST(ValidateRun, APlanStepTakesNoRendererFile) {
  v::ValidateRequest r;
  r.plan = "/nonexistent/jobs.json";
  r.compare_only = true;
  r.export_cache = false;
  r.renderer_files = {"/nonexistent/r.json"};
  EXPECT_NE(errorOf(r).find("the renderer files come from the plan"), std::string::npos) << errorOf(r);
}

TEST(ValidateRun, APlanStepSaysWhatToDo) {
  v::ValidateRequest r;
  r.plan = "/nonexistent/jobs.json";
  r.export_cache = false;
  EXPECT_NE(errorOf(r).find("say what to do"), std::string::npos) << errorOf(r);
}

TEST(ValidateRun, ANewRunNeedsAnOutputFolder) {
  v::ValidateRequest r;
  r.inputs = {kScene};
  r.export_cache = false;
  EXPECT_NE(errorOf(r).find("-o OUTPUT is required"), std::string::npos) << errorOf(r);
}

TEST(ValidateRun, PlanOnlyTakesNoReportSections) {
  const fs::path d = test::freshTempDir("validate_run");
  v::ValidateRequest r;
  r.inputs = {kScene};
  r.output = (d / "out").string();
  r.plan_only = true;
  r.export_cache = false;
  r.sections.extremes = d;
  EXPECT_NE(errorOf(r).find("not --plan-only"), std::string::npos) << errorOf(r);
  EXPECT_FALSE(fs::exists(d / "out"));
}

TEST(ValidateRun, PlanOnlyWritesThePlanAndRendersNothing) {
  const fs::path d = test::freshTempDir("validate_run");
  v::ValidateRequest r;
  r.inputs = {kScene};
  r.output = (d / "out").string();
  r.renderers = {"reference", "povray"};
  r.plan_only = true;
  r.export_cache = false;
  EXPECT_EQ(v::run(r), 0);
  EXPECT_TRUE(fs::is_regular_file(d / "out" / "jobs.json"));
  EXPECT_FALSE(fs::exists(d / "out" / "fig1_phong_behind" / "reference.exr"));
  EXPECT_FALSE(fs::exists(d / "out" / "results.json"));
}
