#include "scene/scene_generator.h"

#include <fstream>
#include <sstream>

#include "scene/scene_loader.h"
#include "scene/scene_writer.h"

namespace xval {

using J = nlohmann::ordered_json;

namespace {

struct Axis {
  std::string name;
  std::vector<std::pair<std::string, J>> values;  // value name -> {pointer: fragment}
};

std::string substitute(std::string tmpl, const std::vector<std::pair<std::string, std::string>>& vars,
                       const std::string& file) {
  for (const auto& [k, v] : vars) {
    const std::string key = "{" + k + "}";
    for (size_t at = tmpl.find(key); at != std::string::npos; at = tmpl.find(key, at + v.size()))
      tmpl.replace(at, key.size(), v);
  }
  if (tmpl.find('{') != std::string::npos)
    throw SceneError(file + ": name: template " + J(tmpl).dump() + " names an axis that does not exist");
  for (char c : tmpl)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      throw SceneError(file + ": name: generated name " + J(tmpl).dump() +
                       " must use only letters, digits, '_', '-' and '.' (it becomes a file name)");
  return tmpl;
}

}  // namespace

std::vector<GeneratedScene> generateScenes(const std::filesystem::path& spec_file) {
  const std::string file = spec_file.string();
  std::ifstream in(spec_file);
  if (!in) throw SceneError(file + ": cannot open the generator spec");
  std::stringstream ss;
  ss << in.rdbuf();
  J spec;
  try {
    spec = J::parse(ss.str());
  } catch (const J::exception& e) {
    throw SceneError(file + ": not valid JSON: " + e.what());
  }
  if (!spec.is_object()) throw SceneError(file + ": expected a JSON object");
  for (auto it = spec.begin(); it != spec.end(); ++it)
    if (it.key() != "format" && it.key() != "base" && it.key() != "axes" && it.key() != "name" &&
        it.key() != "description")
      throw SceneError(file + ": " + it.key() + ": unknown field (known: format, description, base, axes, name)");
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

  std::vector<GeneratedScene> out;
  std::vector<size_t> idx(axes.size(), 0);
  for (;;) {
    J scene = spec["base"];
    std::vector<std::pair<std::string, std::string>> vars;
    std::string combo;
    for (size_t a = 0; a < axes.size(); ++a) {
      const auto& [value_name, patches] = axes[a].values[idx[a]];
      vars.emplace_back(axes[a].name, value_name);
      combo += (combo.empty() ? "" : ", ") + axes[a].name + "=" + value_name;
      for (auto p = patches.begin(); p != patches.end(); ++p) {
        try {
          scene[J::json_pointer(p.key())] = p.value();
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
    // Next combination (the last axis varies fastest).
    size_t a = axes.size();
    while (a > 0 && ++idx[a - 1] == axes[a - 1].values.size()) idx[--a] = 0;
    if (a == 0) break;
  }
  return out;
}

}  // namespace xval
