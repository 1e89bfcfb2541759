// validate's geometry checks (validate/results/geometry_checks.h): the
// record each verdict gives, which records let a case pass, validate's
// default renderers (the geometry check among them), and the JUnit
// testcase of each verdict.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "process/run_process.h"
#include "renderers/registry.h"
#include "support/temp_files.h"
#include "validate/report/junit_report.h"
#include "validate/results/geometry_checks.h"
#include "validate/validation/plan.h"

using namespace xval;
using namespace xval::validation;
using J = nlohmann::ordered_json;

namespace {

GeometryMetrics metrics(bool pass) {
  GeometryMetrics m;
  m.covered = 20000;
  m.mask_off = 3;
  m.mask_off_silhouette = 3;
  m.compared = 19990;
  m.max_depth_rel = 3.3e-6;
  m.uv_compared = 15000;
  m.max_uv = pass ? 1.3e-5 : 0.84;
  m.pass = pass;
  m.why = pass ? "" : "uv error 0.840000 > 0.000100";
  return m;
}

}  // namespace

TEST(GeometryChecks, RecordOfEachVerdict) {
  const J pass = geometryCheckCompared("blender-import", "reference", metrics(true), kGeometryTolerance);
  EXPECT_EQ(pass["verdict"], "pass");
  EXPECT_EQ(pass["renderer"], "blender-import");
  EXPECT_EQ(pass["against"], "reference");
  EXPECT_FALSE(pass.contains("reason"));
  EXPECT_EQ(pass["metrics"]["covered"], 20000);
  EXPECT_EQ(pass["metrics"]["mask_disagree_silhouette"], 3);
  EXPECT_DOUBLE_EQ(pass["bounds"]["max_uv"].get<double>(), kGeometryTolerance.max_uv);
  EXPECT_DOUBLE_EQ(pass["bounds"]["max_depth_rel"].get<double>(), kGeometryTolerance.max_depth_rel);

  const J fail = geometryCheckCompared("blender-import", "reference", metrics(false), kGeometryTolerance);
  EXPECT_EQ(fail["verdict"], "fail");
  EXPECT_EQ(fail["reason"], "uv error 0.840000 > 0.000100");
  EXPECT_DOUBLE_EQ(fail["metrics"]["max_uv"].get<double>(), 0.84);

  const J nexp = geometryCheckNotExpressible("blender-import", "reference", "object 0: a built-in shape");
  EXPECT_EQ(nexp["verdict"], "not_expressible");
  EXPECT_EQ(nexp["reason"], "object 0: a built-in shape");
  EXPECT_FALSE(nexp.contains("metrics"));
  const J err = geometryCheckError("blender-import", "reference", "blender exited 3");
  EXPECT_EQ(err["verdict"], "error");
  EXPECT_FALSE(err.contains("bounds"));
}

TEST(GeometryChecks, ACaseNeedsEveryCheckToPassOrBeNotExpressible) {
  const J pass = geometryCheckCompared("blender-import", "reference", metrics(true), kGeometryTolerance);
  const J fail = geometryCheckCompared("blender-import", "reference", metrics(false), kGeometryTolerance);
  const J nexp = geometryCheckNotExpressible("blender-import", "reference", "why");
  const J err = geometryCheckError("blender-import", "reference", "why");
  EXPECT_TRUE(geometryChecksPass(J::array()));
  EXPECT_TRUE(geometryChecksPass(J::array({pass})));
  EXPECT_TRUE(geometryChecksPass(J::array({nexp})));
  EXPECT_TRUE(geometryChecksPass(J::array({pass, nexp})));
  EXPECT_FALSE(geometryChecksPass(J::array({fail})));
  EXPECT_FALSE(geometryChecksPass(J::array({pass, err})));
  EXPECT_EQ(geometryChecksWith(J::array({pass, fail, nexp, err, fail}), "fail"), 2);
  EXPECT_EQ(geometryChecksWith(J::array({pass, fail, nexp, err}), "not_expressible"), 1);
  EXPECT_EQ(geometryCheckName("reference", "blender-import"), "reference-blender-import (geometry)");
}

// validate runs the check by default, after the image renderers it
// follows in registry order; --renderers can name it, or leave it out.
TEST(GeometryChecks, ValidateRunsTheCheckByDefault) {
  EXPECT_EQ(renderers::registry().validateIds(),
            (std::vector<std::string>{"reference", "povray", "blender", "blender-import", "eevee", "gl"}));
  EXPECT_EQ(jobRenderers(), renderers::registry().validateIds());
  EXPECT_EQ(runRenderers({"blender-import", "reference"}), (std::vector<std::string>{"reference", "blender-import"}));
  EXPECT_EQ(runRenderers({"reference", "povray"}), (std::vector<std::string>{"reference", "povray"}));
  // A restricted renderer (a native tier) when named; it renders the scenes that name it.
  EXPECT_EQ(runRenderers({"reference", "blender-native"}), (std::vector<std::string>{"reference", "blender-native"}));
}

TEST(GeometryChecks, JunitHasOneTestcasePerCheck) {
  const J checks = J::array({geometryCheckCompared("blender-import", "reference", metrics(false), kGeometryTolerance)});
  const J nexp = J::array({geometryCheckNotExpressible("blender-import", "reference", "a built-in shape")});
  const J err = J::array({geometryCheckError("blender-import", "reference", "blender exited 3")});
  const J pass = J::array({geometryCheckCompared("blender-import", "reference", metrics(true), kGeometryTolerance)});
  auto one = [](const std::string& scene, const J& geometry) {
    return J{{"scene", scene},
             {"renders", {{"reference", {{"seconds", 0.5}}}, {"blender-import", {{"seconds", 4.0}}}}},
             {"pairs", J::array()},
             {"geometry_checks", geometry}};
  };
  const nlohmann::json results =
      J{{"format", "xval-results/1"}, {"cases", {one("a", checks), one("b", nexp), one("c", err), one("d", pass)}}};
  const std::string x = junitXml(xval::results::resultsFromJson(xval::results::Json::parse(results.dump()), "results"), "s");
  EXPECT_NE(x.find("tests=\"4\" failures=\"1\" errors=\"1\" skipped=\"1\""), std::string::npos) << x;
  EXPECT_NE(x.find("<testcase classname=\"a\" name=\"reference-blender-import (geometry)\" time=\"4.000\">\n"
                   "      <failure message=\"geometry outside its bounds: uv error 0.840000 &gt; 0.000100; covered "
                   "20000, 0 hit/object disagreements off silhouettes (3 on them), max depth rel. error 3.3e-06 "
                   "(bound 2e-05), max uv error 0.84 (bound 0.0001), 0 edge pixels over\""),
            std::string::npos)
      << x;
  EXPECT_NE(x.find("<skipped message=\"not expressible: a built-in shape\"/>"), std::string::npos) << x;
  EXPECT_NE(x.find("<error message=\"blender exited 3\" type=\"error\">"), std::string::npos) << x;
  EXPECT_NE(x.find("<testcase classname=\"d\" name=\"reference-blender-import (geometry)\" time=\"4.000\"/>"),
            std::string::npos)
      << x;
  // Valid against the JUnit schema the other testcases are checked with.
  const std::filesystem::path dir = test::freshTempDir("xval_geometry_checks_junit");
  std::ofstream(dir / "j.xml") << x;
  const ProcessResult r =
      runProcess({"xmllint", "--noout", "--schema", XVAL_JUNIT_XSD, (dir / "j.xml").string()}, dir, dir / "log", 60);
  EXPECT_TRUE(r.ok()) << r.describe() << "\n" << tailOfFile(r.log);
}
