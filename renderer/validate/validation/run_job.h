// Running the render jobs of `xval validate` (plan.h): one job, or a list
// of them side by side in the job pool (process/job_pool.h).
#pragma once

#include <cstddef>
#include <vector>

#include "validate/validation/job_record.h"
#include "validate/validation/plan.h"

namespace xval::validation {

// Renders the job and writes its EXR, PNG and record. Never throws: a
// failed render is in the returned (and written) record's error; when the
// record itself cannot be written, the returned record is not `present`
// and its error says why.
JobRecord runJob(const Plan& plan, const RenderJob& job);

// The jobs not yet done (all of them unless resuming), in plan order.
std::vector<size_t> jobsToRun(const Plan& plan, bool resume);

// Runs the given jobs (indices into plan.jobs), `workers` at a time, with a
// progress line each on stderr. A job's exception is its record's error.
void runJobs(const Plan& plan, const std::vector<size_t>& todo, int workers);

}  // namespace xval::validation
