// JUnit XML from results.json: one testcase per scene and pair, the outcome
// elements CI systems read, valid against tests/junit/junit.xsd (checked
// with xmllint; a missing xmllint fails the test).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "process/run_process.h"
#include "validate/report/junit_report.h"
#include "support/temp_files.h"

using namespace xval;
using J = nlohmann::json;

namespace {

J sample() {
  J metrics_fail = {{"width", 10},
                    {"height", 10},
                    {"p999_abs_16bit", 9.5},
                    {"max_abs_16bit", 300.0},
                    {"rmse_16bit", 4.0},
                    {"psnr_db", 50.0},
                    {"fraction_within", 0.95},
                    {"mask_disagree", 3},
                    {"mask_disagree_explained", 1},
                    {"max_unexplained_16bit", 12.0},
                    {"over_tolerance", {{"total", 5}, {"precision", 0}, {"edge", 2}, {"backfacing_normal", 0}, {"unexplained", 3}}},
                    {"over_tolerance_max_16bit", {{"precision", 0.0}, {"edge", 9.0}, {"backfacing_normal", 0.0}, {"unexplained", 12.0}}},
                    {"tolerance",
                     {{"max_abs_16bit", 2.0}, {"fraction", 0.999}, {"exclude_backfacing", false}, {"max_unexplained_16bit", 128.0}}},
                    {"tolerance_reason", ""}};
  J metrics_pass = metrics_fail;
  metrics_pass["fraction_within"] = 1.0;
  return {{"format", "xval-results/1"},
          {"cases",
           {{{"scene", "knot <&\"'\x01>"},
             {"renders", {{"reference", {{"seconds", 0.25}}}, {"povray", {{"seconds", 1.5}}}, {"blender", {{"seconds", 2.0}, {"error", "exit code 1 <tail>"}}}}},
             {"pairs",
              {{{"pair", "reference-povray"}, {"pass", true}, {"failed", J::array()}, {"metrics", metrics_pass}},
               {{"pair", "reference-blender"}, {"error", "not compared: a render failed"}},
               {{"pair", "povray-blender"}, {"error", "not compared: a render failed"}}}}},
            {{"scene", "sphere"},
             {"renders", {{"reference", {{"seconds", 0.00001}}}, {"povray", {{"seconds", 1.0}}}}},
             {"pairs",
              {{{"pair", "reference-povray"},
                {"pass", false},
                {"failed",
                 {{{"key", "mask"}, {"text", "2 mask disagreements no edge explains"}, {"brief", "2 mask disagreements"}},
                  {{"key", "fraction"},
                   {"text", "fraction within tolerance 95.00% < 99.9% (5 of 100 pixels outside)"},
                   {"brief", "fraction 95.00% < 99.9%"}}}},
                {"metrics", metrics_fail}},
               {{"pair", "reference-blender"}, {"not_expressible", "blender: spp 9 not supported"}}}}}}}};
}

// JUnit of results.json's JSON, through the results types' reader
// (validate/results/results.h) as every caller's.
std::string junitXml(const J& r, const std::string& suite) {
  return xval::junitXml(xval::results::resultsFromJson(xval::results::Json::parse(r.dump()), "results"), suite);
}

std::filesystem::path dir() {
  static const std::filesystem::path d = xval::test::freshTempDir("xval_junit_test");
  return d;
}

ProcessResult xmllint(const std::string& xml, const char* name) {
  std::ofstream(dir() / name) << xml;
  return runProcess({"xmllint", "--noout", "--schema", XVAL_JUNIT_XSD, (dir() / name).string()}, dir(),
                    dir() / (std::string(name) + ".log"), 60);
}

}  // namespace

TEST(JunitReport, OneTestcasePerScenePairWithItsOutcome) {
  const std::string x = junitXml(sample(), "reference set");
  EXPECT_NE(x.find("<testsuite name=\"reference set\" tests=\"5\" failures=\"1\" errors=\"2\" skipped=\"1\""),
            std::string::npos) << x;
  EXPECT_NE(x.find("<testcase classname=\"sphere\" name=\"reference-povray\""), std::string::npos) << x;
  // The failing criteria first, then the figures.
  EXPECT_NE(x.find("<failure message=\"outside the tolerance: 2 mask disagreements no edge explains; fraction within "
                   "tolerance 95.00% &lt; 99.9% (5 of 100 pixels outside); p99.9 9.5/65535, max 300/65535, 95% within "
                   "2/65535 (needs 99.9%), 2 mask disagreements no edge explains\""),
            std::string::npos) << x;
  EXPECT_NE(x.find("<skipped message=\"not expressible: blender: spp 9 not supported\"/>"), std::string::npos) << x;
  EXPECT_NE(x.find("<error message=\"not compared: a render failed\" type=\"error\">blender: exit code 1 &lt;tail&gt;"),
            std::string::npos) << x;
  // The scene name is escaped, its control character replaced.
  EXPECT_NE(x.find("classname=\"knot &lt;&amp;&quot;&apos;\xEF\xBF\xBD&gt;\""), std::string::npos) << x;
  // time: the two renders' seconds, as a decimal without exponent.
  EXPECT_NE(x.find("name=\"reference-povray\" time=\"1.750\""), std::string::npos) << x;
  EXPECT_NE(x.find("name=\"reference-povray\" time=\"1.000\""), std::string::npos) << x;
}

TEST(JunitReport, ValidAgainstTheSchema) {
  ProcessResult r = xmllint(junitXml(sample(), "reference set"), "ok.xml");
  EXPECT_TRUE(r.ok()) << r.describe() << "\n" << tailOfFile(r.log);
}

// A compared pair's metric-table values (metrics.values) are its testcase's
// properties, in table order, before the outcome; a null one is "not
// finite"; a pair without values has none (results.json from before the
// table). Valid against the schema.
TEST(JunitReport, PairMetricValuesAreTestcaseProperties) {
  J r = sample();
  r["cases"][0]["pairs"][0]["metrics"]["values"] = {{"flip", 0.0125}, {"psnr", nullptr}, {"rmse", 3.5}};
  r["cases"][1]["pairs"][0]["metrics"]["values"] = {{"flip", 0.5}};
  const std::string x = junitXml(r, "reference set");
  EXPECT_NE(x.find("name=\"reference-povray\" time=\"1.750\">\n      <properties>\n"
                   "        <property name=\"metric.rmse\" value=\"3.5\"/>\n"
                   "        <property name=\"metric.psnr\" value=\"not finite\"/>\n"
                   "        <property name=\"metric.flip\" value=\"0.0125\"/>\n      </properties>\n    </testcase>"),
            std::string::npos)
      << x;
  EXPECT_NE(x.find("<property name=\"metric.flip\" value=\"0.5\"/>\n      </properties>\n      <failure "),
            std::string::npos)
      << x;
  EXPECT_EQ(junitXml(sample(), "reference set").find("<properties>"), std::string::npos);
  ProcessResult v = xmllint(x, "properties.xml");
  EXPECT_TRUE(v.ok()) << v.describe() << "\n" << tailOfFile(v.log);
}

TEST(JunitReport, TheSchemaCheckCanFail) {
  // A testcase without classname, a count that is not a number.
  ProcessResult r = xmllint(
      "<?xml version=\"1.0\"?><testsuites><testsuite name=\"s\" tests=\"x\"><testcase name=\"a\"/>"
      "</testsuite></testsuites>",
      "bad.xml");
  ASSERT_TRUE(r.started) << r.describe();
  EXPECT_FALSE(r.ok()) << tailOfFile(r.log);
}

TEST(JunitReport, NotAResultsFileIsAnErrorNamingTheField) {
  try {
    junitXml(J{{"cases", {{{"scene", "a"}}}}}, "s");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "results: cases[0]: no \"pairs\" field");
  }
}

// A case that is no pass never reads as one (issue #30): one that compared
// nothing is a failing testcase of its own (not tests="0"), with why; an
// error case without an erroring testcase gets one.
TEST(JunitReport, ACaseThatComparedNothingIsAFailure) {
  const J r = {{"format", "xval-results/1"},
               {"cases",
                {{{"scene", "limited"},
                  {"renders", {{"reference", {{"seconds", 0.5}}}}},
                  {"pairs", J::array()},
                  {"left_out", {{"golden", "the scene is meant for reference and gl only"}}},
                  {"attribution", "nothing to compare"},
                  {"verdict", "not_compared"},
                  {"pass", false}},
                 {{"scene", "alone"},
                  {"renders", {{"reference", {{"seconds", 0.5}, {"error", "exit code 3"}}}}},
                  {"pairs", J::array()},
                  {"attribution", "nothing to compare"},
                  {"verdict", "error"},
                  {"pass", false}}}}};
  const std::string x = junitXml(r, "set");
  EXPECT_NE(x.find("<testsuite name=\"set\" tests=\"2\" failures=\"1\" errors=\"1\" skipped=\"0\""), std::string::npos)
      << x;
  EXPECT_NE(x.find("<testcase classname=\"limited\" name=\"case\" time=\"0.000\">\n      <failure message=\"nothing "
                   "compared (no image pair, no geometry check): nothing to compare; golden left out: the scene is "
                   "meant for reference and gl only\" type=\"not_compared\"/>"),
            std::string::npos) << x;
  EXPECT_NE(x.find("<testcase classname=\"alone\" name=\"case\" time=\"0.000\">\n      <error message=\"a render "
                   "failed\" type=\"error\">reference: exit code 3\n</error>"),
            std::string::npos) << x;
  ProcessResult lint = xmllint(x, "not_compared.xml");
  EXPECT_TRUE(lint.ok()) << lint.describe() << "\n" << tailOfFile(lint.log);
  // A verdict the testcases already say adds nothing; an unknown one is an error.
  J passing = sample();
  passing["cases"][1]["verdict"] = "fail";
  EXPECT_EQ(junitXml(passing, "reference set"), junitXml(sample(), "reference set"));
  passing["cases"][1]["verdict"] = "maybe";
  EXPECT_THROW(junitXml(passing, "reference set"), std::runtime_error);
}
