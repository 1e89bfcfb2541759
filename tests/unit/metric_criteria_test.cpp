// Metric criteria (image/metric_criteria.h): declared in a tolerance file's
// default and a scene's tolerances, each bound under its metric's better
// direction; the verdict with them (passes, failedCriteria); the lookup of
// a scene's declaration over the default's and the pair of two external
// renderers, which is held to none (validate/tolerances.h).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <set>
#include <stdexcept>
#include <string>

#include "image/metric_criteria.h"
#include "image/pair_failure.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"
#include "validate/tolerances.h"

namespace xval {
namespace {

namespace fs = std::filesystem;

fs::path writeTemp(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("xval_metric_criteria_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

std::string toleranceFile(const std::string& metrics) {
  return R"({"default": {"max_abs_16bit": 2, "fraction": 0.999, "max_unexplained_16bit": 128, "metrics": )" +
         metrics + "}}";
}

TEST(MetricCriteria, TheToleranceFileDeclaresThemInTableOrder) {
  const fs::path f = writeTemp("good.json", toleranceFile(R"({"psnr": {"min": 40}, "flip": {"max": 0.05}})"));
  const Tolerance t = loadTolerances(f).default_tolerance;
  ASSERT_EQ(t.metrics.size(), 2u);
  EXPECT_EQ(t.metrics[0], (MetricCriterion{"psnr", 40}));
  EXPECT_EQ(t.metrics[1], (MetricCriterion{"flip", 0.05}));
  EXPECT_EQ(metricCriteriaText(t.metrics), "psnr min 40, flip max 0.05");
  EXPECT_EQ(metricCriteriaJson(t.metrics), nlohmann::json::parse(R"({"psnr": {"min": 40}, "flip": {"max": 0.05}})"));
  // Without the field: none (the toolkit's own file declares none).
  EXPECT_TRUE(loadTolerances(toolkitToleranceFile()).default_tolerance.metrics.empty());
}

void expectError(const std::string& metrics, std::initializer_list<std::string> said) {
  const fs::path f = writeTemp("bad.json", toleranceFile(metrics));
  try {
    loadTolerances(f);
    FAIL() << "accepted " << metrics;
  } catch (const SceneError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(f.string()), std::string::npos) << what;  // the file
    for (const auto& s : said) EXPECT_NE(what.find(s), std::string::npos) << "no \"" << s << "\" in: " << what;
  }
}

TEST(MetricCriteria, EachBadDeclarationIsAnErrorNamingFileFieldValueAndWhatWasExpected) {
  // An id not in the table: the error lists the table's ids.
  expectError(R"({"fliip": {"max": 0.05}})", {"default.metrics.fliip", "unknown field", "flip", "psnr", "ssim"});
  // The other direction's key: a lower-is-better metric takes "max" ...
  expectError(R"({"flip": {"min": 0.05}})",
              {"default.metrics.flip.min", "mean FLIP is better lower", "expected its bound as \"max\"", "0.05"});
  // ... a higher-is-better one "min".
  expectError(R"({"psnr": {"max": 40}})",
              {"default.metrics.psnr.max", "PSNR is better higher", "expected its bound as \"min\"", "40"});
  // A bound that is not a number, none, or another field beside it.
  expectError(R"({"flip": {"max": "0.05"}})", {"default.metrics.flip.max", "\"0.05\""});
  expectError(R"({"flip": {}})", {"default.metrics.flip.max", "required"});
  expectError(R"({"flip": {"max": 0.05, "why": 1}})", {"default.metrics.flip.why", "unknown field"});
  expectError(R"({"flip": 0.05})", {"default.metrics.flip", "JSON object"});
  expectError(R"([])", {"default.metrics", "JSON object"});
}

TEST(MetricCriteria, AScenesDeclarationIsReadAndWrittenBack) {
  const std::string text =
      R"({"format": "xval-scene/1", "name": "t", "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 8, "height": 8}, "objects": [{"shape": "sphere"}], "material": {"model": {"type": "lambert"}},
          "lights": [{"type": "directional", "direction": [0, 0, -1]}],
          "tolerances": {"gl": {"metrics": {"flip": {"max": 0.05}}, "reason": "a declared FLIP bound, measured"}}})";
  const Scene s = parseScene(text, writeTemp("scene.json", text));
  ASSERT_EQ(s.tolerances.size(), 1u);
  EXPECT_EQ(s.tolerances[0].metrics, (std::vector<MetricCriterion>{{"flip", 0.05}}));
  // The writer writes it in the form read.
  const std::string written = sceneToJson(s).dump();
  EXPECT_EQ(parseScene(written, writeTemp("written.json", written)).tolerances[0].metrics, s.tolerances[0].metrics);
  try {
    const std::string bad = R"({"format": "xval-scene/1", "name": "t", "camera": {"position": [0, 0, 4], "target": [0, 0, 0], "width": 8, "height": 8}, "objects": [{"shape": "sphere"}], "material": {"model": {"type": "lambert"}},
          "lights": [{"type": "directional", "direction": [0, 0, -1]}],
          "tolerances": {"gl": {"metrics": {"ssim": {"max": 0.9}}, "reason": "a declared SSIM bound, measured"}}})";
    parseScene(bad, writeTemp("bad_scene.json", bad));
    FAIL() << "accepted ssim max";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("tolerances.gl.metrics.ssim.max"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("\"min\""), std::string::npos) << e.what();
  }
}

TEST(MetricCriteria, AScenesBoundReplacesTheDefaultsOnThatMetricOnly) {
  ToleranceTable table;
  table.default_tolerance.metrics = {{"psnr", 40}, {"flip", 0.1}};
  Scene s;
  DeclaredTolerance d;
  d.renderer = "gl";
  d.metrics = {{"flip", 0.02}};
  d.reason = "a declared FLIP bound, measured";
  s.tolerances.push_back(d);
  EXPECT_EQ(table.lookup(s, "gl").metrics, (std::vector<MetricCriterion>{{"psnr", 40}, {"flip", 0.02}}));
  EXPECT_EQ(table.lookup(s, "povray").metrics, (std::vector<MetricCriterion>{{"psnr", 40}, {"flip", 0.1}}));
  // With the reference: the other renderer's criteria.
  EXPECT_EQ(table.lookupPair(s, "reference", "gl").metrics, table.lookup(s, "gl").metrics);
  // Two external renderers: none derived, and the reason says which were
  // left to the pairs with the reference.
  std::string reason;
  const Tolerance pair = table.lookupPair(s, "povray", "gl", &reason);
  EXPECT_TRUE(pair.metrics.empty());
  EXPECT_NE(reason.find("gl: psnr min 40, flip max 0.02"), std::string::npos) << reason;
  EXPECT_NE(reason.find("not derived"), std::string::npos) << reason;
}

// A grey square and the same with a band a little brighter.
Image square(float band) {
  Image img(32, 32, true);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      float* p = &img.rgba[(size_t(y) * 32 + x) * 4];
      p[0] = p[1] = p[2] = (y >= 12 && y < 20) ? 0.5f + band : 0.5f;
      p[3] = 1.0f;
    }
  return img;
}

// Pixel criteria that any pair of these images meets: only the metric
// criteria decide.
Tolerance loose(std::vector<MetricCriterion> metrics) {
  Tolerance t;
  t.max_abs = 1.0, t.fraction = 0.0, t.max_unexplained = 1.0;
  t.metrics = std::move(metrics);
  return t;
}

TEST(MetricCriteria, APairOverADeclaredFlipMaxFailsNamingItUnderItPasses) {
  const Image a = square(0), b = square(0.2f);
  const PairMeasures m = measurePair(a, b, loose({}));
  const double flip = m.flip.mean;
  ASSERT_GT(flip, 0.0);
  ASSERT_TRUE(passes(m, loose({})));

  const Tolerance under = loose({{"flip", flip * 2}});
  EXPECT_TRUE(passes(m, under));
  EXPECT_TRUE(failedCriteria(m, under).empty());

  const Tolerance over = loose({{"flip", flip / 2}});
  EXPECT_FALSE(passes(m, over));
  const std::vector<PairFailure> f = failedCriteria(m, over);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].key, "metric:flip");
  EXPECT_NE(f[0].text.find("mean FLIP "), std::string::npos) << f[0].text;
  EXPECT_NE(f[0].text.find(" > max " + std::to_string(flip / 2).substr(0, 4)), std::string::npos) << f[0].text;
  EXPECT_EQ(f[0].brief.rfind("flip ", 0), 0u) << f[0].brief;
  EXPECT_FALSE(failsOnlyOnFraction(f));  // a declared criterion is a hard failure
  // The pair's record says so too.
  const nlohmann::json j = pairJson(m, over);
  EXPECT_FALSE(j["pass"].get<bool>());
  EXPECT_EQ(j["tolerance"]["metrics"], nlohmann::json::parse("{\"flip\": {\"max\": " + nlohmann::json(flip / 2).dump() + "}}"));

  // A higher-is-better metric: PSNR under its min fails, and the text says "<".
  const double psnr = m.compare.psnr_db;
  const std::vector<PairFailure> p = failedCriteria(m, loose({{"psnr", psnr + 10}}));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].key, "metric:psnr");
  EXPECT_NE(p[0].text.find(" dB < min "), std::string::npos) << p[0].text;
  EXPECT_TRUE(passes(m, loose({{"psnr", psnr - 10}})));
  // Equal images: PSNR is infinite, which meets any min.
  EXPECT_TRUE(passes(measurePair(a, a, loose({})), loose({{"psnr", 1e6}})));
}

TEST(MetricCriteria, ThePixelOnlyVerdictRefusesATolerancWithMetricCriteria) {
  const Image a = square(0);
  const PairMeasures m = measurePair(a, a, loose({}));
  EXPECT_THROW(loose({{"flip", 1}}).passes(m.compare), std::logic_error);
  EXPECT_THROW(failedCriteria(m.compare, loose({{"flip", 1}})), std::logic_error);
}

}  // namespace
}  // namespace xval

namespace xval {
namespace {

// docs/results-schema.json lists a failed criterion's keys: metric:ID for
// every id of the table, no other.
TEST(MetricCriteria, TheResultsSchemaNamesEveryMetricsFailureKey) {
  std::ifstream in(fs::path(XVAL_SOURCE_DIR) / "docs/results-schema.json");
  const nlohmann::json schema = nlohmann::json::parse(in);
  std::set<std::string> listed;
  for (const auto& k : schema["definitions"]["pair_failure"]["properties"]["key"]["enum"])
    if (k.get<std::string>().rfind("metric:", 0) == 0) listed.insert(k.get<std::string>());
  std::set<std::string> table;
  for (const MetricInfo& m : metricTable()) table.insert(std::string("metric:") + m.id);
  EXPECT_EQ(listed, table);
}

}  // namespace
}  // namespace xval
