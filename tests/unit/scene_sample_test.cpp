// A generator spec's "sample": a seeded subset of the axes' combinations
// (scene_file/scene_generator.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>

#include "scene_file/scene_generator.h"
#include "scene_file/scene_loader.h"

namespace xval {
namespace {

std::string specWithSample(const std::string& sample) {
  std::string values;
  for (int i = 0; i < 10; ++i) values += std::string(i ? "," : "") + "\"" + std::to_string(i) + "\": {}";
  std::string axes;
  for (int a = 0; a < 6; ++a)  // 10^6 combinations: too many without a sample
    axes += std::string(a ? "," : "") + R"({"name": "a)" + std::to_string(a) + R"(", "values": {)" + values + "}}";
  return R"({"format": "xval-generate/1", "base": {"camera": {"position": [0,0,4], "target": [0,0,0]},
    "objects": [{"shape": "sphere"}], "material": {"model": {"type": "lambert"}}, "lights": []},
    "axes": [)" + axes + R"(], "name": "s_{a0}{a1}{a2}{a3}{a4}{a5}")" +
         (sample.empty() ? "" : ", \"sample\": " + sample) + "}";
}

std::vector<std::string> names(const std::vector<GeneratedScene>& scenes) {
  std::vector<std::string> out;
  for (const auto& g : scenes) out.push_back(g.name);
  return out;
}

std::string errorOf(const std::string& text) {
  try {
    generateScenesFromText(text, "d/spec.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(generated)";
}

TEST(SceneSample, DrawsCountDistinctCombinationsInOrderTheSameForTheSameSeed) {
  const auto a = generateScenesFromText(specWithSample(R"({"count": 40, "seed": 7})"), "d/spec.json");
  ASSERT_EQ(a.size(), 40u);
  const std::vector<std::string> n = names(a);
  EXPECT_EQ(std::set<std::string>(n.begin(), n.end()).size(), 40u);  // no repeats
  EXPECT_TRUE(std::is_sorted(n.begin(), n.end()));  // combination order (equal-width names)
  EXPECT_EQ(names(generateScenesFromText(specWithSample(R"({"count": 40, "seed": 7})"), "d/spec.json")), n);
  EXPECT_NE(names(generateScenesFromText(specWithSample(R"({"count": 40, "seed": 8})"), "d/spec.json")), n);
  // Spread over the product, not its first values: some scene varies the first axis.
  EXPECT_TRUE(std::any_of(n.begin(), n.end(), [](const std::string& s) { return s[2] != '0'; }));
}

TEST(SceneSample, TheSequenceIsFixed) {
  // SplitMix64 from seed 1, reduced mod 1000 and sorted (computed apart, in
  // Python): a change of the generator would silently change every
  // generated set.
  EXPECT_EQ(sampleCombinations(1000, 3, 1), (std::vector<uint64_t>{465, 519, 590}));
  // All of them: every index once.
  const auto all = sampleCombinations(50, 50, 3);
  for (uint64_t i = 0; i < 50; ++i) EXPECT_EQ(all[i], i);
  EXPECT_THROW(sampleCombinations(5, 6, 0), std::invalid_argument);
}

TEST(SceneSample, BadSamplesAreRefusedByName) {
  EXPECT_EQ(errorOf(specWithSample("")),
            "d/spec.json: axes: more than 10000 combinations (the product of the axes' value counts); take a "
            "\"sample\" of them");
  EXPECT_NE(errorOf(specWithSample(R"({"count": 0, "seed": 1})")).find("d/spec.json: sample.count: 0 ("),
            std::string::npos);
  EXPECT_NE(errorOf(specWithSample(R"({"count": 3})")).find("d/spec.json: sample.seed: required"), std::string::npos);
  EXPECT_NE(errorOf(specWithSample(R"({"count": 3, "seed": -1})")).find("sample.seed: -1"), std::string::npos);
  EXPECT_NE(errorOf(specWithSample(R"({"count": 3, "seed": 1, "n": 2})")).find("sample.n: unknown field"),
            std::string::npos);
  EXPECT_NE(errorOf(specWithSample("[3]")).find("d/spec.json: sample: expected {"), std::string::npos);
  const std::string small = R"({"format": "xval-generate/1", "base": {"camera": {"position": [0,0,4], "target": [0,0,0]},
    "objects": [{"shape": "sphere"}], "material": {"model": {"type": "lambert"}}, "lights": []},
    "axes": [{"name": "a", "values": {"x": {}, "y": {}}}], "name": "s_{a}", "sample": {"count": 3, "seed": 1}})";
  EXPECT_EQ(errorOf(small), "d/spec.json: sample.count: 3 is more than the 2 combinations of the axes");
}

}  // namespace
}  // namespace xval
