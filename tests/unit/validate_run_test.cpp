// validation::run (validate/validation/validate_run.h): a request decides
// the step; a request that cannot run is refused before anything is
// written, and --plan-only writes the plan and renders nothing.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "support/temp_files.h"
#include "validate/validation/plan.h"
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

// A crosscheck's run (validate/validation/crosscheck.h) is validate's with the
// reference and one renderer, any the registry has but the reference:
// blender-native, which validate's --renderers refuses, too; its plan is
// read back (readPlan: planRenderers) and runs as any.
TEST(ValidateRun, ACrosscheckPlansTheReferenceAndAnyOneRenderer) {
  EXPECT_EQ(v::crosscheckRenderers("blender-native"), (std::vector<std::string>{"reference", "blender-native"}));
  EXPECT_EQ(v::crosscheckRenderers("golden:reference"), (std::vector<std::string>{"reference", "golden"}));
  EXPECT_THROW(v::crosscheckRenderers("reference"), std::runtime_error);
  EXPECT_THROW(v::crosscheckRenderers("no-such-renderer"), std::runtime_error);
  EXPECT_EQ(v::planRenderers({"reference", "blender-native"}),
            (std::vector<std::string>{"reference", "blender-native"}));
  EXPECT_THROW(v::planRenderers({"reference", "blender-native", "povray"}), std::runtime_error);

  const fs::path d = test::freshTempDir("validate_run");
  v::ValidateRequest r;
  r.inputs = {kScene};
  r.output = (d / "out").string();
  r.crosscheck_renderer = "blender-native";
  r.plan_only = true;
  r.export_cache = false;
  EXPECT_EQ(v::run(r), 0);
  const v::Plan plan = v::readPlan(d / "out" / "jobs.json");
  EXPECT_EQ(plan.renderers, (std::vector<std::string>{"reference", "blender-native"}));
  EXPECT_EQ(plan.jobs.size(), 2u);
}

// A scene whose `renderers` field does not name the crosschecked renderer
// is an error naming the file and the field (validate leaves it out).
TEST(ValidateRun, ACrosscheckRefusesASceneNotMeantForItsRenderer) {
  const fs::path d = test::freshTempDir("validate_run");
  const fs::path scene = XVAL_REFERENCE_DIR "/../tests/cli/scenes/not_expressible/meant_for_two.json";
  v::ValidateRequest r;
  r.inputs = {scene.string()};
  r.output = (d / "out").string();
  r.crosscheck_renderer = "povray";
  r.plan_only = true;
  r.export_cache = false;
  EXPECT_NE(errorOf(r).find("meant_for_two.json: renderers: the scene is meant for reference and blender only, not povray"),
            std::string::npos)
      << errorOf(r);
  r.crosscheck_renderer.clear();
  r.renderers = {"reference", "povray"};
  EXPECT_EQ(v::run(r), 0);  // validate: left out, said on stderr
}

// A crosscheck's folder holds that one crosscheck: an earlier run there
// with other renderers is replaced (validate would refuse to keep its
// cases: plan_update.h).
TEST(ValidateRun, ACrosscheckReplacesAnEarlierRunInItsFolder) {
  const fs::path d = test::freshTempDir("validate_run");
  v::ValidateRequest r;
  r.inputs = {kScene};
  r.output = (d / "out").string();
  r.renderers = {"reference", "golden"};  // rendered: its case could be kept
  r.export_cache = false;
  ASSERT_EQ(v::run(r), 0);
  r.renderers.clear();
  r.plan_only = true;
  r.inputs = {XVAL_REFERENCE_DIR "/scenes/light_spot.json"};  // another scene
  r.crosscheck_renderer = "povray";
  EXPECT_EQ(v::run(r), 0) << errorOf(r);
  const v::Plan plan = v::readPlan(d / "out" / "jobs.json");
  EXPECT_EQ(plan.renderers, (std::vector<std::string>{"reference", "povray"}));
  ASSERT_EQ(plan.scenes.size(), 1u);  // fig1_phong_behind's case not kept
  EXPECT_EQ(plan.scenes[0].name, "light_spot");
}
