// Updating an output folder's cases (plan_update.h).
#include "validate/validation/plan_update.h"

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

#include "renderers/registry.h"
#include "validate/validation/job_record.h"

namespace xval::validation {

namespace fs = std::filesystem;

namespace {

bool isLeftOut(const std::vector<LeftOut>& left_out, const std::string& renderer) {
  return std::any_of(left_out.begin(), left_out.end(), [&](const LeftOut& l) { return l.renderer == renderer; });
}

}  // namespace

std::optional<Plan> earlierPlan(const Plan& plan) {
  const fs::path file = planFile(plan.dir);
  if (!fs::exists(file)) return std::nullopt;
  try {
    return readPlan(file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "xval validate: the folder's earlier plan does not read, no earlier case kept: %s\n",
                 e.what());
    return std::nullopt;
  }
}

PlanUpdate keepEarlierScenes(Plan& plan, const Plan& earlier) {
  PlanUpdate out;
  std::set<fs::path> paths;
  std::set<std::string> names;
  for (const PlannedScene& s : plan.scenes) paths.insert(s.path), names.insert(s.name);
  bool refused = false;
  for (const PlannedScene& s : earlier.scenes) {
    if (paths.count(s.path)) continue;  // validated again: updated
    if (earlier.renderers != plan.renderers) {
      refused = true;
      break;
    }
    auto drop = [&](const std::string& why) { out.dropped.push_back(s.path.string() + ": " + why); };
    if (names.count(s.name)) {
      drop("dropped: this run validates another scene file named \"" + s.name + "\" into its case folder");
      continue;
    }
    std::error_code ec;
    if (!fs::is_regular_file(s.path, ec)) {
      drop("dropped: the scene file no longer exists");
      continue;
    }
    Scene scene;
    try {
      scene = loadScene(s.path, plan.budget);
    } catch (const std::exception& e) {
      drop(std::string("dropped: the scene file no longer loads: ") + e.what());
      continue;
    }
    if (scene.name != s.name) {
      drop("dropped: the scene's name is now \"" + scene.name + "\" (was \"" + s.name + "\"): validate it again");
      continue;
    }
    PlannedScene kept = s;
    kept.kept = true;
    std::vector<RenderJob> jobs;
    std::string why;
    for (const std::string& r : plan.renderers) {
      if (isLeftOut(kept.left_out, r)) continue;
      RenderJob job;
      job.index = plan.jobs.size() + jobs.size();
      job.scene = s.name, job.file = s.file, job.path = s.path, job.renderer = r;
      job.input_hash = inputHash(scene, job.path, r);
      if (!isDone(plan, job, &why)) break;
      jobs.push_back(job);
    }
    if (!why.empty()) {
      drop("dropped: its renders are not current (" + why + "): validate it again");
      continue;
    }
    plan.jobs.insert(plan.jobs.end(), jobs.begin(), jobs.end());
    plan.scenes.push_back(std::move(kept));
    paths.insert(s.path), names.insert(s.name);
    ++out.kept;
  }
  if (refused)
    throw std::runtime_error(plan.dir.string() + " holds cases validated with the renderers " +
                             renderers::joinNames(earlier.renderers) + "; this run's are " +
                             renderers::joinNames(plan.renderers) +
                             ": those cases cannot be kept beside this run's (validate with the same --renderers, "
                             "or into another output folder)");
  return out;
}

std::vector<size_t> withoutKept(const Plan& plan, const std::vector<size_t>& todo) {
  std::set<std::string> kept;
  for (const PlannedScene& s : plan.scenes)
    if (s.kept) kept.insert(s.name);
  std::vector<size_t> out;
  for (size_t k : todo)
    if (!kept.count(plan.jobs[k].scene)) out.push_back(k);
  return out;
}

}  // namespace xval::validation
