#include "validate/tolerances.h"
#include "renderers/registry.h"

#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "image/metric_criteria.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"

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
  table.default_tolerance.metrics = readMetricCriteria(d, "metrics");
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
    t.metrics = overriddenCriteria(t.metrics, d.metrics);
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
  // No metric criterion is derived (the rule in tolerances.h): t.metrics
  // stays empty, and the reason says which were left to the reference pairs.
  if (reason) {
    *reason = "derived: the sum of the " + a + " and " + b +
              " tolerances on f1 + f2 - 1 of the pixels (triangle inequality and union bound)";
    std::string left;
    for (const auto& [id, ti] : {std::pair{&a, &t1}, std::pair{&b, &t2}})
      if (!ti->metrics.empty()) left += (left.empty() ? "" : "; ") + *id + ": " + metricCriteriaText(ti->metrics);
    if (!left.empty())
      *reason += "; the metric criteria (" + left + ") are not derived for this pair: no triangle inequality "
                 "bounds them, they hold on each renderer's pair with " + reference;
  }
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
// folder up to its set root; empty when there is none.
fs::path nearestToleranceFile(const fs::path& scene_file) {
  const fs::path root = setRootOf(scene_file);
  fs::path dir = fs::absolute(scene_file).lexically_normal().parent_path();
  for (;;) {
    const fs::path candidate = dir / "tolerances.json";
    std::error_code ec;
    if (fs::exists(fs::symlink_status(candidate, ec))) return candidate;
    if (dir == root || !dir.has_relative_path()) return {};
    dir = dir.parent_path();
  }
}

std::string modeText(mode_t m) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "%04o", unsigned(m & 07777));
  return buf;
}

std::string userText(uid_t uid) {
  const struct passwd* pw = getpwuid(uid);
  return "uid " + std::to_string(uid) + (pw ? " (" + std::string(pw->pw_name) + ")" : "");
}

// Why the tolerance file `file`, found for `scene_file` by step 2, may not
// decide verdicts ("" when it may): the ownership rule of tolerances.h.
std::string untrustedReason(const fs::path& file, const fs::path& scene_file) {
  struct stat scene_st, link_st, file_st, dir_st;
  if (stat(scene_file.c_str(), &scene_st) != 0) return "the scene file cannot be examined: " + std::string(std::strerror(errno));
  const auto trusted = [&](uid_t uid) { return uid == geteuid() || uid == 0 || uid == scene_st.st_uid; };
  const std::string allowed = "only one owned by you (uid " + std::to_string(geteuid()) +
                              "), by the scene file's owner (uid " + std::to_string(scene_st.st_uid) +
                              ") or by root is used";
  if (lstat(file.c_str(), &link_st) != 0 || stat(file.c_str(), &file_st) != 0)
    return "it cannot be examined: " + std::string(std::strerror(errno));
  if (S_ISLNK(link_st.st_mode) && !trusted(link_st.st_uid))
    return "it is a symbolic link owned by " + userText(link_st.st_uid) + "; " + allowed;
  if (!S_ISREG(file_st.st_mode)) return "it is not a regular file";
  if (!trusted(file_st.st_uid)) return "it is owned by " + userText(file_st.st_uid) + "; " + allowed;
  if (file_st.st_mode & S_IWOTH) return "it is writable by every user (mode " + modeText(file_st.st_mode) + ")";
  const fs::path dir = file.parent_path();
  if (stat(dir.c_str(), &dir_st) != 0) return "its folder cannot be examined: " + std::string(std::strerror(errno));
  if ((dir_st.st_mode & S_IWOTH) && !(dir_st.st_mode & S_ISVTX))
    return "its folder " + dir.string() + " is writable by every user without the sticky bit (mode " +
           modeText(dir_st.st_mode) + "): anyone can replace it";
  return "";
}

}  // namespace

fs::path setRootOf(const fs::path& scene_file) {
  const fs::path own = fs::absolute(scene_file).lexically_normal().parent_path();
  for (fs::path dir = own; dir.has_relative_path(); dir = dir.parent_path())
    if (dir.filename() == "scenes") return dir.parent_path();
  return own;
}

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
                               " (the nearest tolerances.json in the scene's folder or above, up to its set root); give one with "
                               "--tolerances FILE");
    }
  }
  if (found.empty()) return {toolkitToleranceFile(), "the toolkit's own"};
  if (const std::string why = untrustedReason(found, found_for); !why.empty())
    throw std::runtime_error(found.string() + ": the tolerance file nearest to " + found_for.string() +
                             " is not used: " + why + " (a file there would decide the verdict); pass it with "
                             "--tolerances FILE if you trust it, or remove it");
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
