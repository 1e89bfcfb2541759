// The compare step of `xval validate` (plan.h): from the plan, the job
// records and the EXRs, every case compared pair by pair, results.json
// (results_file.h) and, from it alone, report.html (validate/report/report.h).
//
// A case is one scene: its renders (each an image, an error: no record, a
// failed render, a record from other inputs, an unreadable EXR; or the
// renderer's declaration that it cannot express the scene, with its
// reason), every unordered pair of the renderers it has jobs for, in
// registry order (renderers::unorderedPairs), compared with the tolerance
// declared for that scene and pair (validate/tolerances.h), each pair's
// difference EXR and heat map PNG written into the case folder (the files of
// the kinds validate/compare_outputs.h names that the case's results do not
// name, an earlier run's, are removed from it, and their count said), and who
// deviates (renderers::attribute, among the renderers that can express
// it). A pair with a failed render is an error ("error"); a pair with a
// renderer that cannot express the scene is not compared and not an error
// ("not_expressible": the reason). The case's verdict is decided once,
// here (case_verdict.h): it passes when something was compared and every
// pair that could be compared passes; a case that compared nothing is
// "not_compared", never a pass. The renderers its `renderers` field left
// out are its "left_out", with the reason.
#pragma once

#include <chrono>
#include <exception>
#include <memory>
#include <mutex>
#include <vector>

#include "validate/report/report.h"
#include "validate/validation/image_handoff.h"
#include "validate/validation/plan.h"

namespace xval::validation {

// The compare step in parts, so that a run can compare each case as soon
// as its renders are done, beside the renders still running (run_job.h
// runJobs' after_case), and then write the verdict:
//   CaseComparer c(plan, sections);   // checks the sections, removes the old verdict
//   c.compare(k) for every scene k, in any order, from any threads
//   c.finish()                        // results.json, report.html, next steps
// Every case's result is kept in its plan slot, so results.json lists the
// cases in plan order whatever order they were compared in. A case that
// throws stops the step at finish(): the first such case in plan order.
class CaseComparer {
 public:
  // Throws (before anything is compared) when the sections' folders hold no
  // results or the tolerance file cannot be read.
  // With `images`, a case takes the renders its jobs left there
  // (image_handoff.h) instead of reading their EXRs.
  CaseComparer(const Plan& plan, const ReportSections& sections, ImageHandoff* images = nullptr);
  ~CaseComparer();
  // Compares plan.scenes[k] (every pair, the difference images into its
  // folder) and prints a progress line. Never throws (the case's exception
  // is kept for finish()); call it once per case, from any thread.
  void compare(size_t k);
  // Once every case is compared: rethrows the first case's exception in
  // plan order, else writes results.json and report.html and prints the
  // next steps. Returns the exit status (compareAndReport).
  int finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// Compares every pair of every scene, writes results.json and report.html,
// prints the next steps of the cases that do not pass (next_steps.h).
// Returns the exit status of `xval validate` (validateExitStatus): 0 every
// case passes (a renderer that cannot express a scene is no failure, as
// long as the case compared something), 1 some case outside its tolerance
// or compared nothing, 2 an error (a render failed or a job has no usable
// record).
// `workers` cases are compared at once (process/job_pool.h); the results
// do not depend on it.
int compareAndReport(const Plan& plan, const ReportSections& sections = {}, int workers = 1);

}  // namespace xval::validation
