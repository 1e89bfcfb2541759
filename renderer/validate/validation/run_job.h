// Running the render jobs of `xval validate` (plan.h): one job, a batch of
// one renderer's jobs in one outside process, or a list of them side by
// side in the job pool (process/job_pool.h), weighted by what they use.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "validate/validation/image_handoff.h"
#include "validate/validation/job_record.h"
#include "validate/validation/plan.h"

namespace xval::validation {

// Renders the job and writes its EXR, PNG and record. Never throws: a
// failed render is in the returned (and written) record's error; when the
// record itself cannot be written, the returned record is not `present`
// and its error says why.
// With `images`, its EXR as read back is left there for its case's compare
// (image_handoff.h).
JobRecord runJob(const Plan& plan, const RenderJob& job, ImageHandoff* images = nullptr);

// The jobs not yet done (all of them unless resuming), in plan order.
std::vector<size_t> jobsToRun(const Plan& plan, bool resume);

// Renders several jobs of one renderer that renders batches
// (Renderer::render_batch: Blender's persistent worker) together, each job
// with the same steps, checks and record as runJob; one record per job, in
// order. Never throws for a job's failure. `job_done`, when not empty, is
// called once per job (its place k in `jobs`) as soon as its record is
// written, for a scene Blender's worker finished while the batch renders
// on (Renderer::render_batch's item_done), one call at a time.
using JobDone = std::function<void(size_t k, const JobRecord&)>;
std::vector<JobRecord> runJobBatch(const Plan& plan, const std::vector<size_t>& jobs, const JobDone& job_done = {},
                                   ImageHandoff* images = nullptr);

// How runJobs schedules.
struct RunSettings {
  // The cores to keep busy: `workers` CPU-bound jobs at once.
  int workers = 1;
  // Scenes per batch for a renderer that renders batches: 0 automatic (the
  // renderer's jobs split evenly over the workers, at most kMaxBatch per
  // batch), 1 none (one process per scene, as every job once was).
  size_t batch = 0;
  // true: a job takes its renderer's cpu_share of a core
  // (renderers/renderer.h), so tools that mostly wait run more at once;
  // false: `workers` jobs at once whatever they use.
  bool by_load = true;
};
inline constexpr size_t kMaxBatch = 32;

// Work on a case that follows its renders (the compare of the case,
// compare_step.h CaseComparer::compare), run in the same pool as the jobs.
struct AfterCase {
  std::function<void(size_t scene)> run;  // plan.scenes index; should not throw
  double weight = 1.0;                    // its share of a core (a compare is CPU-bound: 1)
  // Where the jobs leave their images for `run` (image_handoff.h: what
  // reading their EXRs would give, without decoding them again), or null.
  ImageHandoff* images = nullptr;
};

// Runs the given jobs (indices into plan.jobs) as `settings` says, with a
// progress line each on stderr. A job's exception is its record's error.
// Returns the jobs' records, in the order of `todo`.
//
// Order: the pool's tasks (a Blender batch, or one job) start longest
// first, by their jobs' estimated seconds (job_cost.h; a batch: the sum of
// its jobs'); equal ones in plan order. The records and the files are the
// same whatever the order.
//
// With `after_case`, after_case->run(k) runs once for every scene k of the
// plan, as a task of the same pool: for a scene with jobs in `todo`, queued
// when the last of them has ended (its record written), ahead of every job
// not yet started (so a case is compared while the other jobs render); for
// a scene without (done before, --resume; kept, plan_update.h), queued
// after every job at the start. runJobs returns when every job and every
// after_case->run has returned.
std::vector<JobRecord> runJobs(const Plan& plan, const std::vector<size_t>& todo, const RunSettings& settings,
                               const AfterCase* after_case = nullptr);

// The jobs of a job list as `validate --run-jobs` takes it (what a Slurm
// array task renders, scripts/slurm/submit.sh): plan indices and ranges
// separated by commas, "0-3,7,9-11", in the order given. Throws
// std::runtime_error naming the item for an item that is not a number or
// a range LO-HI with LO <= HI, an index not below job_count, or an index
// given twice.
std::vector<size_t> parseJobList(const std::string& list, size_t job_count);

}  // namespace xval::validation
