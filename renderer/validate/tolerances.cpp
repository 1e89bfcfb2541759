#include "validate/tolerances.h"

#include <fstream>
#include <sstream>

#include "scene/json_reader.h"

namespace xval {

namespace {
Tolerance readTolerance(JsonReader& r, const Tolerance& base) {
  Tolerance t = base;
  t.max_abs = r.number("max_abs_16bit", base.max_abs * 65535.0, Range::nonNegative()) / 65535.0;
  t.fraction = r.number("fraction", base.fraction, Range::closed(0.0, 1.0));
  t.exclude_backfacing = r.boolean("exclude_backfacing", false);
  return t;
}
}  // namespace

ToleranceTable loadTolerances(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw SceneError(file.string() + ": cannot open tolerance file");
  std::stringstream ss;
  ss << in.rdbuf();
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(ss.str(), nullptr, true, /*ignore_comments=*/false);
  } catch (const nlohmann::json::exception& e) {
    throw SceneError(file.string() + ": not valid JSON: " + e.what());
  }
  ToleranceTable table;
  table.source = file;
  JsonReader r(doc, "", file.string());
  r.string("description", "");
  {
    JsonReader d = r.requireObject("default");
    table.default_tolerance = readTolerance(d, Tolerance{});
    d.finish();
  }
  for (auto& c : r.objectArray("cases", false)) {
    ToleranceCase tc;
    tc.scenes = c.stringArray("scenes", true);
    if (tc.scenes.empty()) c.failValue("scenes", "a non-empty array of scene names");
    tc.renderer = c.requireChoice("renderer", {"povray", "blender", "blender-native"});
    tc.tolerance = readTolerance(c, table.default_tolerance);
    tc.reason = c.string("reason", "");
    const Tolerance& d = table.default_tolerance;
    bool loosens = tc.tolerance.max_abs > d.max_abs || tc.tolerance.fraction < d.fraction ||
                   tc.tolerance.exclude_backfacing;
    if (loosens && tc.reason.size() < 20)
      c.fail("reason", "an exception that loosens the default needs a written reason (at least a "
                       "sentence), got " + describeJson(tc.reason));
    c.finish();
    table.cases.push_back(std::move(tc));
  }
  r.finish();
  return table;
}

Tolerance ToleranceTable::lookup(const std::string& scene, const std::string& renderer,
                                 std::string* reason) const {
  for (const auto& c : cases) {
    if (c.renderer != renderer) continue;
    for (const auto& s : c.scenes)
      if (s == scene) {
        if (reason) *reason = c.reason;
        return c.tolerance;
      }
  }
  if (reason) reason->clear();
  return default_tolerance;
}

}  // namespace xval
