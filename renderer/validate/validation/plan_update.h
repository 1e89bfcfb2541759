// Validating some scenes into an output folder that holds an earlier run:
// the run updates those cases and keeps the others, so results.json and
// the report still cover every case of the folder.
//
// Cases are keyed by their scene file's absolute path. For each scene of
// the earlier plan (OUT/jobs.json, read before the new one replaces it), in
// its order, after the new run's own scenes:
//   - the new run validates the same file: updated (nothing kept);
//   - the new run validates another file of the same name: dropped (the
//     case folder OUT/<name> is now that file's);
//   - the scene file no longer exists, no longer loads, or its name
//     changed: dropped;
//   - a render of it is not done for the new plan (jobRecord: the scene
//     file, its texture or model file changed since, or an image or record
//     is missing): dropped, since its renders no longer show the scene;
//   - otherwise kept: its jobs join the plan, marked kept, and are not run
//     again; the compare step compares its renders again, with this run's
//     tolerances, like every other case.
// Every dropped scene is said on stderr with the reason. The earlier plan
// must have the run's renderers: a case made with other renderers cannot
// be compared like the new ones, so the run refuses (use the same
// --renderers, or another output folder).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "validate/validation/plan.h"

namespace xval::validation {

struct PlanUpdate {
  size_t kept = 0;                    // scenes kept
  std::vector<std::string> dropped;   // one line per dropped scene: file, reason
};

// Adds the kept scenes of `earlier` to `plan` (after its own, jobs
// appended, indices continued). Throws std::runtime_error when the
// renderers differ.
PlanUpdate keepEarlierScenes(Plan& plan, const Plan& earlier);

// The earlier plan of plan.dir, when the folder has one that reads; a plan
// that does not read is said on stderr and none is kept.
std::optional<Plan> earlierPlan(const Plan& plan);

// The jobs of `todo` that belong to scenes the run validates (not kept).
std::vector<size_t> withoutKept(const Plan& plan, const std::vector<size_t>& todo);

}  // namespace xval::validation
