#include "scene_file/scene_generator.h"

#include <algorithm>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>
#include <sstream>

#include "scene_file/scene_loader.h"
#include "scene_file/scene_writer.h"

namespace xval {

using J = nlohmann::ordered_json;

namespace {

struct Axis {
  std::string name;
  std::vector<std::pair<std::string, J>> values;  // value name -> {pointer: fragment}
};

std::string substitute(const std::string& tmpl,
                       const std::vector<std::pair<std::string, std::string>>& vars,
                       const std::string& file) {
  // One pass over the template: each {axis} is replaced by the value's
  // name; the result is checked as it grows (it becomes a file name).
  std::string out;
  for (size_t at = 0; at < tmpl.size();) {
    const size_t open = tmpl.find('{', at);
    out.append(tmpl, at, open == std::string::npos ? std::string::npos : open - at);
    if (open == std::string::npos) break;
    const size_t close = tmpl.find('}', open);
    const std::string axis =
        close == std::string::npos ? std::string() : tmpl.substr(open + 1, close - open - 1);
    auto v = std::find_if(vars.begin(), vars.end(), [&](const auto& kv) { return kv.first == axis; });
    if (close == std::string::npos || v == vars.end())
      throw SceneError(file + ": name: template " + describeJson(J(tmpl)) +
                       " names an axis that does not exist");
    out += v->second;
    if (out.size() > kMaxSceneNameBytes)
      throw SceneError(file + ": name: template " + describeJson(J(tmpl)) + " gives a name longer than " +
                       std::to_string(kMaxSceneNameBytes) + " bytes");
    at = close + 1;
  }
  // The name is then checked by the one scene-name rule (sceneNameProblem)
  // when the generated scene is parsed, before anything is written.
  return out;
}

// Applies one patch. The pointer may reach at most kMaxJsonDepth deep and
// may extend an array by one element at most ("/lights/1" on a one-light
// array, or "/lights/-"): "/lights/99999999" would otherwise allocate a
// hundred million nulls.
void applyPatch(J& scene, const std::string& pointer, const J& value, const std::string& where) {
  J::json_pointer ptr(pointer);  // throws on bad syntax
  std::vector<std::string> tokens;
  for (J::json_pointer p = ptr; !p.empty(); p.pop_back()) {
    tokens.push_back(p.back());
    if (tokens.size() > size_t(kMaxJsonDepth))
      throw SceneError(where + ": JSON pointer deeper than " + std::to_string(kMaxJsonDepth) + " levels");
  }
  std::reverse(tokens.begin(), tokens.end());
  const J* cur = &scene;
  for (const std::string& t : tokens) {
    const bool numeric = !t.empty() && t.find_first_not_of("0123456789") == std::string::npos;
    const size_t size = cur && cur->is_array() ? cur->size() : 0;
    const bool creates_array = !cur || cur->is_null();
    if ((cur && cur->is_array()) || (creates_array && numeric)) {
      if (t != "-" && numeric && (t.size() > 9 || std::stoul(t) > size))
        throw SceneError(where + ": " + describeJson(J(pointer)) + ": index " + t +
                         " is past the end of the array (size " + std::to_string(size) +
                         "; an index may add one element)");
    }
    if (!cur || !cur->is_structured()) {
      cur = nullptr;  // created from here on (or an error the pointer reports)
    } else if (cur->is_object()) {
      auto it = cur->find(t);
      cur = it == cur->end() ? nullptr : &*it;
    } else {
      cur = numeric && t.size() <= 9 && std::stoul(t) < cur->size() ? &(*cur)[std::stoul(t)] : nullptr;
    }
  }
  scene[ptr] = value;
}

struct Sample {
  size_t count = 0;
  uint64_t seed = 0;
};

// The spec's optional "sample": {"count": N, "seed": S}.
std::optional<Sample> readSample(const J& spec, const std::string& file) {
  if (!spec.contains("sample")) return std::nullopt;
  const J& s = spec["sample"];
  const std::string what = "expected {\"count\": an integer in [1, " + std::to_string(kMaxGeneratedScenes) +
                           "], \"seed\": an integer in [0, 2^53]}";
  if (!s.is_object()) throw SceneError(file + ": sample: " + what + ", got " + describeJson(s));
  for (auto it = s.begin(); it != s.end(); ++it)
    if (it.key() != "count" && it.key() != "seed")
      throw SceneError(file + ": sample." + it.key() + ": unknown field (known: count, seed)");
  auto integer = [&](const char* key, uint64_t lo, uint64_t hi) {
    if (!s.contains(key)) throw SceneError(file + ": sample." + key + ": required; " + what);
    const J& v = s[key];
    if (!v.is_number_unsigned() || v.get<uint64_t>() < lo || v.get<uint64_t>() > hi)
      throw SceneError(file + ": sample." + key + ": " + describeJson(v) + " (" + what + ")");
    return v.get<uint64_t>();
  };
  Sample out;
  out.count = size_t(integer("count", 1, kMaxGeneratedScenes));
  out.seed = integer("seed", 0, uint64_t(1) << 53);
  return out;
}

}  // namespace

std::vector<uint64_t> sampleCombinations(uint64_t combinations, size_t count, uint64_t seed) {
  if (count > combinations)
    throw std::invalid_argument("sampleCombinations: " + std::to_string(count) + " of " +
                                std::to_string(combinations) + " combinations");
  // SplitMix64 (a fixed, portable sequence: the standard library's
  // distributions differ between implementations), each draw reduced to
  // [0, combinations) by rejecting the top partial range, so every index is
  // equally likely; a repeated index is drawn again.
  uint64_t state = seed;
  auto next = [&state]() {
    uint64_t z = (state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  };
  const uint64_t limit = UINT64_MAX - UINT64_MAX % combinations;
  std::set<uint64_t> chosen;
  while (chosen.size() < count) {
    uint64_t r;
    do r = next();
    while (r >= limit);
    chosen.insert(r % combinations);
  }
  return {chosen.begin(), chosen.end()};
}

namespace {

}  // namespace

std::vector<GeneratedScene> generateScenes(const std::filesystem::path& spec_file) {
  return generateScenesFromText(readJsonFile(spec_file, "generator spec"), spec_file);
}

std::vector<GeneratedScene> generateScenesFromText(const std::string& text,
                                                   const std::filesystem::path& spec_file) {
  const std::string file = spec_file.string();
  J spec = parseOrderedJsonText(text, file);
  if (!spec.is_object()) throw SceneError(file + ": expected a JSON object");
  for (auto it = spec.begin(); it != spec.end(); ++it)
    if (it.key() != "format" && it.key() != "base" && it.key() != "axes" && it.key() != "name" &&
        it.key() != "description" && it.key() != "sample")
      throw SceneError(file + ": " + it.key() +
                       ": unknown field (known: format, description, base, axes, name, sample)");
  if (spec.value("format", "") != "xval-generate/1")
    throw SceneError(file + ": format: expected \"xval-generate/1\", got " +
                     (spec.contains("format") ? spec["format"].dump() : std::string("nothing")));
  if (!spec.contains("base") || !spec["base"].is_object())
    throw SceneError(file + ": base: required, expected a JSON object (a scene file's fields)");
  if (!spec.contains("name") || !spec["name"].is_string())
    throw SceneError(file + ": name: required, expected a template string such as \"{model}_{shading}\"");
  std::vector<Axis> axes;
  if (!spec.contains("axes") || !spec["axes"].is_array() || spec["axes"].empty())
    throw SceneError(file + ": axes: required, expected a non-empty array");
  for (size_t i = 0; i < spec["axes"].size(); ++i) {
    const J& a = spec["axes"][i];
    const std::string where = file + ": axes[" + std::to_string(i) + "]";
    if (!a.is_object() || !a.contains("name") || !a["name"].is_string() || !a.contains("values") ||
        !a["values"].is_object() || a["values"].empty())
      throw SceneError(where + ": expected {\"name\": string, \"values\": {value name: {JSON pointer: value}}}");
    Axis axis{a["name"].get<std::string>(), {}};
    for (auto v = a["values"].begin(); v != a["values"].end(); ++v) {
      if (!v.value().is_object())
        throw SceneError(where + ".values." + v.key() + ": expected an object of JSON pointer -> value");
      axis.values.emplace_back(v.key(), v.value());
    }
    axes.push_back(std::move(axis));
  }
  const std::optional<Sample> sample = readSample(spec, file);
  size_t combinations = 1;
  for (const auto& a : axes) {
    if (combinations > kMaxSampledCombinations / a.values.size())
      throw SceneError(file + ": axes: more than " + std::to_string(kMaxSampledCombinations) +
                       " combinations (the product of the axes' value counts)");
    combinations *= a.values.size();
    if (!sample && combinations > kMaxGeneratedScenes)
      throw SceneError(file + ": axes: more than " + std::to_string(kMaxGeneratedScenes) +
                       " combinations (the product of the axes' value counts); take a \"sample\" of them");
  }
  if (sample && sample->count > combinations)
    throw SceneError(file + ": sample.count: " + std::to_string(sample->count) + " is more than the " +
                     std::to_string(combinations) + " combinations of the axes");
  const std::vector<uint64_t> chosen =
      sample ? sampleCombinations(combinations, sample->count, sample->seed) : std::vector<uint64_t>();

  std::vector<GeneratedScene> out;
  const size_t total = sample ? chosen.size() : combinations;
  for (size_t n = 0; n < total; ++n) {
    // The combination's value per axis: its index in mixed radix, the last
    // axis varying fastest.
    uint64_t index = sample ? chosen[n] : n;
    std::vector<size_t> idx(axes.size(), 0);
    for (size_t a = axes.size(); a > 0; --a) {
      idx[a - 1] = size_t(index % axes[a - 1].values.size());
      index /= axes[a - 1].values.size();
    }
    J scene = spec["base"];
    std::vector<std::pair<std::string, std::string>> vars;
    std::string combo;
    for (size_t a = 0; a < axes.size(); ++a) {
      const auto& [value_name, patches] = axes[a].values[idx[a]];
      vars.emplace_back(axes[a].name, value_name);
      combo += (combo.empty() ? "" : ", ") + axes[a].name + "=" + value_name;
      for (auto p = patches.begin(); p != patches.end(); ++p) {
        try {
          applyPatch(scene, p.key(), p.value(),
                     file + ": axes[" + std::to_string(a) + "].values." + value_name);
        } catch (const J::exception& e) {
          throw SceneError(file + ": axes[" + std::to_string(a) + "].values." + value_name + ": " +
                           J(p.key()).dump() + " is not a usable JSON pointer: " + e.what());
        }
      }
    }
    std::string name = substitute(spec["name"].get<std::string>(), vars, file);
    J named = {{"format", "xval-scene/1"}, {"name", name}};
    for (auto f = scene.begin(); f != scene.end(); ++f)
      if (f.key() != "format" && f.key() != "name") named[f.key()] = f.value();
    scene = std::move(named);
    // Validate as a scene file, relative paths against the spec's folder.
    Scene s;
    try {
      s = parseScene(scene.dump(), spec_file.parent_path() / (name + ".json"));
    } catch (const SceneError& e) {
      throw SceneError(file + ": combination (" + combo + ") gives an invalid scene: " + e.what());
    }
    for (const auto& g : out)
      if (g.name == name)
        throw SceneError(file + ": name: two combinations are both named " + J(name).dump() +
                         "; put every axis in the template");
    out.push_back({name, scene});
  }
  return out;
}

namespace {

void rebasePaths(J& node, const std::filesystem::path& from_dir, const std::filesystem::path& to_dir) {
  namespace fs = std::filesystem;
  if (node.is_array()) {
    for (auto& e : node) rebasePaths(e, from_dir, to_dir);
    return;
  }
  if (!node.is_object()) return;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (it.key() == "path" && it.value().is_string()) {
      const fs::path p(it.value().get<std::string>());
      if (p.empty() || p.is_absolute()) continue;
      // Canonical (symlinks resolved) on both sides, so ".." steps in the
      // result walk the real folders.
      const fs::path target = fs::weakly_canonical(fs::absolute(from_dir / p));
      const fs::path rel = target.lexically_relative(fs::weakly_canonical(fs::absolute(to_dir)));
      it.value() = (rel.empty() ? target : rel).generic_string();
    } else {
      rebasePaths(it.value(), from_dir, to_dir);
    }
  }
}

}  // namespace

nlohmann::ordered_json sceneForFolder(const GeneratedScene& g, const std::filesystem::path& spec_file,
                                      const std::filesystem::path& out_dir) {
  J scene = g.json;
  rebasePaths(scene, spec_file.parent_path(), out_dir);
  return scene;
}

}  // namespace xval
