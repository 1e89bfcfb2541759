// The whole of `xval validate` behind its arguments: one request, one
// function that chooses the step (a plain run, --plan-only, --run-job,
// --run-jobs, --compare-only) and returns the exit status. The command
// line (cli/cmd_validate.cpp) only parses arguments into a ValidateRequest
// and calls run; the steps themselves are plan.h, plan_update.h,
// run_job.h and compare_step.h.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/export_common.h"
#include "scene_file/scene_budget.h"
#include "validate/report/report.h"
#include "validate/validation/run_job.h"

namespace xval::validation {

struct ValidateRequest {
  // A new run (plan, render, compare), unless `plan` is given.
  std::vector<std::string> inputs;     // scene files or folders (scene_file/scene_set.h); empty: the toolkit's set
  std::string output;                  // the output folder (-o); required for a new run
  std::string tolerances;              // the tolerance file; empty: found by the one rule (tolerances.h)
  std::vector<std::string> renderers;  // as given to --renderers (runRenderers); empty: jobRenderers()
  double timeout_seconds = kDefaultToolTimeoutSeconds;
  Budget budget;
  // A crosscheck's run (validate/validation/crosscheck.h): the reference and this one
  // renderer (crosscheckRenderers, plan.h), in place of `renderers`; a
  // scene not meant for it is an error, not left out (NotMeantFor::Refuse);
  // an earlier run in the folder is replaced, its cases not kept.
  std::string crosscheck_renderer;
  bool resume = false;     // keep the earlier run's finished jobs (jobsToRun)
  bool plan_only = false;  // write the plan, print the jobs to run, render nothing

  // One step of a plan written before (--plan FILE): exactly one of
  // run_job, run_jobs and compare_only.
  std::string plan;
  std::optional<size_t> run_job;
  std::string run_jobs;  // a job list (parseJobList)
  bool compare_only = false;

  RunSettings settings;     // for the renders (a new run, run_jobs); workers also for compare_only
  ReportSections sections;  // the compare step's report sections (a new run, compare_only)
  std::string junit;        // after the compare step: its JUnit XML to this file; empty: none

  std::vector<std::string> renderer_files;  // renderer definition files to add (a new run only)
  bool export_cache = true;                 // exports through the export cache (renderers/export_cache.h)
  std::filesystem::path export_cache_dir;   // empty: renderers::defaultExportCacheFolder()
};

// Runs the request and returns validate's exit status (cli/cmd_validate.cpp
// says which: 0, 1 or 2). Throws std::runtime_error (or SceneError) naming
// the file, field or argument for an error before or outside the jobs: a
// bad request (a plan step with renderer files or none to do, sections for
// a step that does not compare, a new run without an output folder), a
// bad scene or plan, a locked folder.
int run(const ValidateRequest& request);

}  // namespace xval::validation
