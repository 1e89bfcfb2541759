// validation::run (validate/validation/validate_run.h): a request decides
// the step; a request that cannot run is refused before anything is
// written, and --plan-only writes the plan and renders nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
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
// blender-native too; its plan is
// read back (readPlan: planRenderers) and runs as any.
TEST(ValidateRun, ACrosscheckPlansTheReferenceAndAnyOneRenderer) {
  EXPECT_EQ(v::crosscheckRenderers("blender-native"), (std::vector<std::string>{"reference", "blender-native"}));
  EXPECT_EQ(v::crosscheckRenderers("golden:reference"), (std::vector<std::string>{"reference", "golden"}));
  EXPECT_THROW(v::crosscheckRenderers("reference"), std::runtime_error);
  EXPECT_THROW(v::crosscheckRenderers("no-such-renderer"), std::runtime_error);
  EXPECT_EQ(v::planRenderers({"reference", "blender-native"}),
            (std::vector<std::string>{"reference", "blender-native"}));
  // validate's --renderers takes blender-native too, for the scenes that name it.
  EXPECT_EQ(v::planRenderers({"reference", "blender-native", "povray"}),
            (std::vector<std::string>{"reference", "povray", "blender-native"}));

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

// A restricted renderer (Renderer::restricted: a native tier such as
// blender-native) renders exactly the scenes that name it: validate
// without --renderers takes it when a scene names it, leaves it out of the
// others (recorded in the plan, since the jobs follow from it, but not
// said), and a run given its renderers takes it only when named.
TEST(ValidateRun, ARestrictedRendererRendersTheScenesThatNameIt) {
  const fs::path d = test::freshTempDir("validate_run");
  fs::create_directories(d / "set");
  const std::string plain = test::fileText(fs::path(XVAL_REFERENCE_DIR) / "../tests/cli/scenes/tiny.json");
  std::string named = plain;
  const std::string key = "\"format\": \"xval-scene/1\",";
  ASSERT_NE(named.find(key), std::string::npos);
  named.replace(named.find(key), key.size(),
                key + " \"renderers\": [\"reference\", \"blender-native\"],");
  named.replace(named.find("\"tiny\""), 6, "\"native\"");
  std::ofstream(d / "set" / "a_plain.json") << plain;
  std::ofstream(d / "set" / "b_native.json") << named;
  v::ValidateRequest r;
  r.inputs = {(d / "set").string()};
  r.output = (d / "out").string();
  r.plan_only = true;
  r.export_cache = false;
  ASSERT_EQ(v::run(r), 0);
  v::Plan plan = v::readPlan(d / "out" / "jobs.json");
  ASSERT_NE(std::find(plan.renderers.begin(), plan.renderers.end(), "blender-native"), plan.renderers.end());
  ASSERT_EQ(plan.scenes.size(), 2u);
  std::map<std::string, std::vector<std::string>> jobs;
  for (const v::RenderJob& job : plan.jobs) jobs[job.scene].push_back(job.renderer);
  EXPECT_EQ(jobs["native"], (std::vector<std::string>{"reference", "blender-native"}));
  EXPECT_EQ(std::count(jobs["tiny"].begin(), jobs["tiny"].end(), "blender-native"), 0);
  EXPECT_GE(jobs["tiny"].size(), 2u);
  const auto& plain_left = plan.scenes[0].left_out;
  ASSERT_EQ(plain_left.size(), 1u);
  EXPECT_EQ(plain_left[0].renderer, "blender-native");
  EXPECT_TRUE(v::leftOutUnsaid(plain_left[0]));

  // Given its renderers, a run takes blender-native only when named.
  r.output = (d / "out2").string();
  r.renderers = {"reference", "povray"};
  ASSERT_EQ(v::run(r), 0);
  plan = v::readPlan(d / "out2" / "jobs.json");
  EXPECT_EQ(plan.renderers, (std::vector<std::string>{"reference", "povray"}));
  r.output = (d / "out3").string();
  r.renderers = {"reference", "blender-native"};
  ASSERT_EQ(v::run(r), 0);
  plan = v::readPlan(d / "out3" / "jobs.json");
  jobs.clear();
  for (const v::RenderJob& job : plan.jobs) jobs[job.scene].push_back(job.renderer);
  EXPECT_EQ(jobs["native"], (std::vector<std::string>{"reference", "blender-native"}));
  EXPECT_EQ(jobs["tiny"], (std::vector<std::string>{"reference"}));
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
