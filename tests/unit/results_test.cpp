// results.json's types (validate/results/results.h): read -> write -> read
// gives the same results, the written file keeps every field of the one
// read (only the pairs' stored verdicts added) and validates against
// docs/results-schema.json (Ajv, tests/tools/validate_json_schema.js); a
// stored verdict the fields contradict is refused naming the field.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "process/run_process.h"
#include "support/temp_files.h"
#include "validate/results/results.h"

namespace xval {
namespace {

namespace fs = std::filesystem;
using results::Json;

std::string text(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path dir() {
  static const fs::path d = test::freshTempDir("xval_results_test");
  return d;
}

// The files read: the published run's results and the fuzzing seeds.
std::vector<fs::path> samples() {
  return {fs::path(XVAL_SOURCE_DIR) / "results/validation/results.json",
          fs::path(XVAL_TESTS_DIR) / "fuzz/seeds/results/pass.json",
          fs::path(XVAL_TESTS_DIR) / "fuzz/seeds/results/error.json",
          // a pair failing a declared metric criterion (tolerance.metrics)
          fs::path(XVAL_TESTS_DIR) / "fuzz/seeds/results/metric_fail.json"};
}

// `j` without the pairs' "verdict", unordered (order is no part of the format).
nlohmann::json withoutPairVerdicts(const Json& j) {
  nlohmann::json out = nlohmann::json::parse(j.dump());
  for (auto& c : out["cases"])
    for (auto& p : c["pairs"]) p.erase("verdict");
  return out;
}

TEST(Results, ReadWriteReadIsTheSame) {
  for (const fs::path& f : samples()) {
    SCOPED_TRACE(f.string());
    const results::Results first = results::readResults(f);
    ASSERT_FALSE(first.cases.empty());
    const fs::path written = dir() / (f.parent_path().filename().string() + "_" + f.filename().string());
    results::writeResults(written, first);
    const results::Results second = results::readResults(written);
    EXPECT_TRUE(first == second);
    // Every field of the file read is in the file written.
    EXPECT_EQ(withoutPairVerdicts(Json::parse(text(written))), withoutPairVerdicts(Json::parse(text(f))));
    // ... and every pair has its verdict.
    // (The parsed file named: a range-for over a temporary's member would
    // read it after it is destroyed.)
    const Json written_json = Json::parse(text(written));
    for (const auto& c : written_json["cases"])
      for (const auto& p : c["pairs"]) EXPECT_TRUE(p.contains("verdict")) << p.dump();
    ASSERT_FALSE(std::string(XVAL_NODE).empty()) << "node not found: the schema check cannot run";
    const ProcessResult v = runProcess({XVAL_NODE, (fs::path(XVAL_SOURCE_DIR) / "tests/tools/validate_json_schema.js").string(),
                                        (fs::path(XVAL_SOURCE_DIR) / "docs/results-schema.json").string(), written.string()},
                                       dir(), dir() / (written.filename().string() + ".ajv.log"), 60);
    EXPECT_TRUE(v.ok()) << v.describe() << "\n" << tailOfFile(v.log);
  }
}

// The verdicts a reader sees are the stored ones: a pair's and a case's.
TEST(Results, TheVerdictsAreTheStoredOnes) {
  const results::Results r = results::readResults(fs::path(XVAL_TESTS_DIR) / "fuzz/seeds/results/error.json");
  for (const results::Case& c : r.cases) {
    ASSERT_TRUE(c.verdict.has_value()) << c.scene;
    for (const results::Pair& p : c.pairs)
      if (p.error) {
        EXPECT_EQ(p.verdict, results::PairVerdict::Error) << p.pair;
      }
  }
}

TEST(Results, AStoredVerdictTheFieldsContradictIsRefusedNamingTheField) {
  Json j = Json::parse(text(fs::path(XVAL_TESTS_DIR) / "fuzz/seeds/results/pass.json"));
  ASSERT_TRUE(j["cases"][0]["pairs"][0]["pass"].get<bool>());
  j["cases"][0]["pairs"][0]["verdict"] = "fail";
  const fs::path f = dir() / "contradiction.json";
  std::ofstream(f) << j.dump(2);
  try {
    results::readResults(f);
    FAIL() << "a pass stored as fail was read";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(f.string() + ": cases[0].pairs[0].verdict: \"fail\"", 0), 0u) << e.what();
  }
  j["cases"][0]["pairs"][0]["verdict"] = "maybe";  // not a verdict: the schema refuses it first
  std::ofstream(f) << j.dump(2);
  EXPECT_THROW(results::readResults(f), std::runtime_error);
}

// A pair held to a scene's finding: outside the tolerance it is a
// `finding` (read, written back, valid against the schema); the verdict
// its fields imply is the stored one's check, as for any pair.
TEST(Results, AFindingPairIsReadWrittenAndChecked) {
  Json j = Json::parse(text(fs::path(XVAL_TESTS_DIR) / "fuzz/seeds/results/pass.json"));
  Json& p = j["cases"][0]["pairs"][0];
  ASSERT_TRUE(p["pass"].get<bool>());
  p["pass"] = false;
  p["failed"] = Json::array({{{"key", "fraction"}, {"text", "fraction within tolerance 50% < 99.9%"}, {"brief", "50% < 99.9% within"}}});
  p["finding"] = {{"renderer", "povray"}, {"why", "its phong highlight is gated by N.L"}};
  p["verdict"] = "finding";
  j["cases"][0]["pass"] = true;
  const fs::path f = dir() / "finding.json";
  std::ofstream(f) << j.dump(2);
  const results::Results r = results::readResults(f);
  const results::Pair& read = r.cases[0].pairs[0];
  EXPECT_EQ(read.verdict, results::PairVerdict::Finding);
  ASSERT_TRUE(read.finding.has_value());
  EXPECT_EQ(read.finding->renderer, "povray");
  const fs::path written = dir() / "finding_written.json";
  results::writeResults(written, r);
  EXPECT_TRUE(results::readResults(written) == r);
  // Within the tolerance, a finding no longer holds: the fields say fail.
  p["pass"] = true;
  p["failed"] = Json::array();
  std::ofstream(f) << j.dump(2);
  try {
    results::readResults(f);
    FAIL() << "a finding within the tolerance was read as a finding";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("pairs[0].verdict: \"finding\" but the pair's fields say \"fail\""),
              std::string::npos)
        << e.what();
  }
  // A finding without one: the fields say fail.
  p["pass"] = false;
  p["failed"] = Json::array({{{"key", "fraction"}, {"text", "t"}, {"brief", "b"}}});
  p.erase("finding");
  std::ofstream(f) << j.dump(2);
  EXPECT_THROW(results::readResults(f), std::runtime_error);
}

}  // namespace
}  // namespace xval
