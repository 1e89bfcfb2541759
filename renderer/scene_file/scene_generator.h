// Scene sets generated from a matrix spec (`xval generate`).
//
// Spec file (JSON):
//   {
//     "format": "xval-generate/1",
//     "base": { ...a scene file's fields... },
//     "axes": [
//       {"name": "model", "values": {
//          "phong": {"/material/model": {"type": "classic_phong"}},
//          "yiq":   {"/material/model": {"type": "yiq_luma"}}}},
//       {"name": "placement", "values": {
//          "front":    {"/lights/0/position": [-0.5, 2.0, 1.25]},
//          "specular": {"/material/model/kd": 0}}},
//       ...
//     ],
//     "name": "fig1_{model}_{placement}"
//   }
//     "sample": {"count": 60, "seed": 1}   (optional)
// Every combination of one value per axis (in axis order) gives a scene:
// the base with each value's JSON-pointer patches applied in turn (later
// axes override earlier ones), named by the template. Each scene is then
// validated like a scene file; an error names the spec, the combination
// and the field. With "sample", only `count` of the combinations, drawn
// without repetition by sampleCombinations(product, count, seed), are
// written, in combination order: a seeded set of ordinary scenes from axes
// whose product is too large to render whole (tests/mutation/generated_spec.json).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace xval {

struct GeneratedScene {
  std::string name;
  nlohmann::ordered_json json;  // the scene file's content
};

// At most this many scenes per spec: the combinations, or the sample's count.
inline constexpr size_t kMaxGeneratedScenes = 10000;
// At most this many combinations a sample is drawn from (the product of the
// axes' value counts).
inline constexpr uint64_t kMaxSampledCombinations = uint64_t(1) << 53;

// `count` distinct indices in [0, combinations), in increasing order, drawn
// by a fixed pseudo-random sequence from `seed`: the same on every machine
// and compiler. Throws std::invalid_argument when count > combinations.
std::vector<uint64_t> sampleCombinations(uint64_t combinations, size_t count, uint64_t seed);

std::vector<GeneratedScene> generateScenes(const std::filesystem::path& spec_file);

// Same, from the spec's text already in memory; `spec_file` names it in
// messages, and relative texture paths resolve against its folder.
std::vector<GeneratedScene> generateScenesFromText(const std::string& text,
                                                   const std::filesystem::path& spec_file);

// The scene file `g` written into `out_dir`: its relative file paths (every
// string field named "path": textures, model files) rewritten from the
// spec's folder to `out_dir`, so they name the same files from there
// (relative when both lie under one root, else absolute).
nlohmann::ordered_json sceneForFolder(const GeneratedScene& g, const std::filesystem::path& spec_file,
                                      const std::filesystem::path& out_dir);

}  // namespace xval
