#include "validate/tolerances.h"

#include <fstream>
#include <sstream>

#include "scene/json_reader.h"
#include "scene/scene_loader.h"

namespace xval {

ToleranceTable loadTolerances(const std::filesystem::path& file) {
  // As a scene file: a duplicated key, deep nesting or a number beyond a
  // double is an error naming the field.
  const nlohmann::json doc = parseJsonText(readJsonFile(file, "tolerance file"), file.string());
  ToleranceTable table;
  table.source = file;
  JsonReader r(doc, "", file.string());
  r.string("description", "");
  JsonReader d = r.requireObject("default");
  table.default_tolerance.max_abs = d.requireNumber("max_abs_16bit", Range::nonNegative()) / 65535.0;
  table.default_tolerance.fraction = d.requireNumber("fraction", Range::closed(0.0, 1.0));
  d.finish();
  r.finish();
  return table;
}

Tolerance ToleranceTable::lookup(const Scene& scene, const std::string& renderer,
                                 std::string* reason) const {
  Tolerance t = default_tolerance;
  if (reason) reason->clear();
  for (const auto& d : scene.tolerances) {
    if (d.renderer != renderer) continue;
    if (d.max_abs_16bit) t.max_abs = *d.max_abs_16bit / 65535.0;
    if (d.fraction) t.fraction = *d.fraction;
    t.exclude_backfacing = d.exclude_backfacing;
    if (reason) *reason = d.reason;
  }
  return t;
}

}  // namespace xval
