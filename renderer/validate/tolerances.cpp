#include "validate/tolerances.h"
#include "renderers/registry.h"

#include <algorithm>
#include <stdexcept>

#include "scene/json_reader.h"
#include "scene/scene_loader.h"

#ifndef XVAL_TOOLKIT_TOLERANCES
#error "XVAL_TOOLKIT_TOLERANCES (the toolkit's reference/tolerances.json) is set by renderer/CMakeLists.txt"
#endif

namespace xval {

namespace fs = std::filesystem;

ToleranceTable loadTolerances(const fs::path& file) {
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
  table.default_tolerance.max_unexplained =
      d.requireNumber("max_unexplained_16bit", Range::nonNegative()) / 65535.0;
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
    if (d.max_unexplained_16bit) t.max_unexplained = *d.max_unexplained_16bit / 65535.0;
    t.exclude_backfacing = d.exclude_backfacing;
    if (reason) *reason = d.reason;
  }
  return t;
}

Tolerance ToleranceTable::lookupPair(const Scene& scene, const std::string& a, const std::string& b,
                                     std::string* reason) const {
  const std::string& reference = renderers::registry().reference().id;
  if (a == reference) return lookup(scene, b, reason);
  if (b == reference) return lookup(scene, a, reason);
  const Tolerance t1 = lookup(scene, a), t2 = lookup(scene, b);
  Tolerance t;
  t.max_abs = t1.max_abs + t2.max_abs;
  t.fraction = std::max(0.0, t1.fraction + t2.fraction - 1.0);
  t.max_unexplained = t1.max_unexplained + t2.max_unexplained;
  t.exclude_backfacing = t1.exclude_backfacing || t2.exclude_backfacing;
  if (reason)
    *reason = "derived: the sum of the " + a + " and " + b +
              " tolerances on f1 + f2 - 1 of the pixels (triangle inequality and union bound)";
  return t;
}

std::string ToleranceFile::shown() const {
  std::error_code ec;
  const fs::path rel = path.lexically_relative(fs::current_path(ec));
  if (ec || rel.empty() || *rel.begin() == "..") return path.string();
  return rel.string();
}

fs::path toolkitToleranceFile() { return fs::path(XVAL_TOOLKIT_TOLERANCES).lexically_normal(); }

fs::path toolkitSceneSet() { return toolkitToleranceFile().parent_path() / "scenes"; }

std::string defaultScenesHelp() {
  return "Scene files or folders (default: the toolkit's own scene set, " + toolkitSceneSet().string() +
         ", whatever the working directory)";
}

namespace {

// Step 2 of the rule: the nearest tolerances.json from the scene file's
// folder up to the root; empty when there is none.
fs::path nearestToleranceFile(const fs::path& scene_file) {
  fs::path dir = fs::absolute(scene_file).lexically_normal().parent_path();
  for (;;) {
    const fs::path candidate = dir / "tolerances.json";
    std::error_code ec;
    if (fs::exists(candidate, ec)) return candidate;
    if (!dir.has_relative_path()) return {};  // the root
    dir = dir.parent_path();
  }
}

}  // namespace

ToleranceFile findToleranceFile(const fs::path& given, const std::vector<fs::path>& scene_files) {
  if (!given.empty()) return {fs::absolute(given).lexically_normal(), "given"};
  fs::path found, found_for;
  for (const auto& scene : scene_files) {
    const fs::path f = nearestToleranceFile(scene);
    if (f.empty()) continue;
    if (found.empty()) {
      found = f, found_for = scene;
    } else if (f != found) {
      throw std::runtime_error("the scenes find different tolerance files: " + found_for.string() + " finds " +
                               found.string() + ", " + scene.string() + " finds " + f.string() +
                               " (the nearest tolerances.json in the scene's folder or above); give one with "
                               "--tolerances FILE");
    }
  }
  if (found.empty()) return {toolkitToleranceFile(), "the toolkit's own"};
  // A scene that finds none would use the toolkit's file: that must be the
  // same file too.
  for (const auto& scene : scene_files)
    if (nearestToleranceFile(scene).empty() && found != toolkitToleranceFile())
      throw std::runtime_error("the scenes find different tolerance files: " + found_for.string() + " finds " +
                               found.string() + ", " + scene.string() + " finds none, so the toolkit's own " +
                               toolkitToleranceFile().string() + "; give one with --tolerances FILE");
  return {found, "nearest to the scene"};
}

}  // namespace xval
