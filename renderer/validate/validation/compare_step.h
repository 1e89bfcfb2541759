// The compare step of `xval validate` (plan.h): from the plan, the job
// records and the EXRs, every case compared pair by pair, results.json
// (results_file.h) and, from it alone, report.html (validate/report.h).
//
// A case is one scene: its renders (each an image, an error: no record, a
// failed render, a record from other inputs, an unreadable EXR; or the
// renderer's declaration that it cannot express the scene, with its
// reason), every unordered pair of the renderers it has jobs for, in
// registry order (renderers::unorderedPairs), compared with the tolerance
// declared for that scene and pair (validate/tolerances.h), each pair's
// difference EXR and heat map PNG written into the case folder, and who
// deviates (renderers::attribute, among the renderers that can express
// it). A pair with a failed render is an error ("error"); a pair with a
// renderer that cannot express the scene is not compared and not an error
// ("not_expressible": the reason). The case passes when every pair that
// could be compared passes; the renderers its `renderers` field left out
// are its "left_out", with the reason.
#pragma once

#include "validate/report.h"
#include "validate/validation/plan.h"

namespace xval::validation {

// Compares every pair of every scene, writes results.json and report.html,
// prints the failing cases' next steps (next_steps.h). Returns the exit
// status of `xval validate`: 0 every compared pair passes (a renderer that
// cannot express a scene is no failure), 1 some case outside its
// tolerance, 2 an error (a render failed or a job has no usable record).
// `workers` cases are compared at once (process/job_pool.h); the results
// do not depend on it.
int compareAndReport(const Plan& plan, const ReportSections& sections = {}, int workers = 1);

}  // namespace xval::validation
