// xval validate [SCENES or DIRS...] -o results/<run>/ [--jobs N] [--timeout S] [--resume]
//               [--batch N] [--schedule load|count]
//               [--renderers LIST] [--tolerances FILE] [--extremes DIR] [--tradeoff DIR]
// xval validate [SCENES or DIRS...] -o OUT --plan-only [--resume]
// xval validate --plan OUT/jobs.json --run-job K
// xval validate --plan OUT/jobs.json --run-jobs LIST [--jobs N] [--batch N] [--schedule load|count]
// xval validate --plan OUT/jobs.json --compare-only
//
// Renders every scene with every every-scene renderer of the registry
// (renderers/registry.h: the reference renderer, POV-Ray, Blender Cycles
// and EEVEE, gl), compares every pair (reference-povray, ...,
// povray-blender, ...) with the declared tolerances, attributes each disagreement, and writes
// results.json and, from it alone, report.html (validate/report/report.h).
//
// The work is split into jobs (validate/validation/plan.h): a plan
// (OUT/jobs.json, one render job per scene and renderer, every output path
// fixed), render jobs, and the compare/report step. A plain run does all
// three in this process (the render jobs in a thread pool); --plan-only,
// --run-job and --compare-only do one step each, which is how a cluster
// runs it (scripts/slurm/submit.sh, docs/cluster.md). --run-jobs renders
// a list of the plan's jobs (a Slurm array task's batch) the way a plain
// run renders all of them, with the same scheduling.
//
// Scheduling (validate/validation/run_job.h): the jobs start longest
// first (by an estimate from the scene's size, job_cost.h), and a plain
// run compares each case as soon as its jobs are done, in the same pool
// as the renders still running (a compare takes a core); results.json
// keeps the plan's order. Blender's jobs (blender,
// eevee) go to persistent workers, one Blender process per --batch scenes
// (default: split evenly over the --jobs workers, at most 32 each; 1: one
// process per scene); with --schedule load (default) a job takes its
// renderer's measured share of a core, so that POV-Ray, which mostly
// waits, runs several jobs per core, while CPU-bound jobs never exceed
// --jobs; --schedule count runs --jobs jobs at once whatever they use.
//
// The Blender-import check (blender-import: Blender imports the scene's
// original model files itself) runs by default as each case's geometry
// check: its passes against the reference's, with their own bounds, not an
// image pair (validate/results/geometry_checks.h); a scene it cannot
// take (a built-in shape, an OFF file) records it as not expressible, with
// the reason. --renderers leaves it out unless it names blender-import.
//
// --renderers LIST renders and compares only those renderers; a scene's
// `renderers` field leaves out the others for that scene (each said on
// stderr and in results.json); a renderer that declares it cannot express
// a scene is recorded as not expressible, with its reason, and the case
// is decided on the other pairs (validate/validation/compare_step.h). A
// scene meant for the reference renderer takes `golden` (its stored
// images) in its place. A case that compares nothing (no pair, no geometry
// check) is NOT COMPARED, never a pass (validate/results/case_verdict.h).
//
// Exit 0: every case compared something and every compared pair is within
// tolerance; 1: some case outside, or a case that compared nothing; 2: an
// error (bad scene, renderer missing or broken, a job not run). --plan-only
// exits 0 when it wrote the plan; --run-job exits 0 when the render
// succeeded and 2 when it failed (the failure is in the job's record);
// --run-jobs 0 when every job of the list succeeded, 2 when any failed.
// Files are written whole or not at all (files/atomic_write.h), so an
// interrupted run leaves no file that looks complete; the output folder is
// locked (files/output_folder.h: a plain run, --plan-only and
// --compare-only alone, --run-job shared), and a new run removes the old
// results.json and report.html before it plans.
//
// Exports (POV-Ray's, the glTF for Blender) and the exporters' refusals go
// through the export cache (renderers/export_cache.h): --export-cache DIR,
// default $XDG_CACHE_HOME/xval/exports or ~/.cache/xval/exports;
// --no-export-cache exports every scene.
//
// This file parses the arguments into a ValidateRequest; the run itself,
// which step and in what order, is validation::run
// (validate/validation/validate_run.h).
//
// Scenes into a folder that holds an earlier run: those cases are updated
// and the folder's other cases kept (compared again from their renders,
// not rendered again), or dropped with the reason on stderr when their
// scene file is gone or changed (validate/validation/plan_update.h).
#include <cstdio>
#include <functional>
#include <memory>
#include <stdexcept>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/renderer_file_option.h"
#include "common/export_common.h"
#include "process/job_pool.h"
#include "renderers/registry.h"
#include "validate/report/report.h"
#include "validate/tolerances.h"
#include "validate/validation/plan.h"
#include "validate/validation/validate_run.h"

namespace xval::cli {

namespace {
namespace v = xval::validation;

// validate's arguments as parsed.
struct Args {
  std::vector<std::string> inputs, renderers;
  std::string dir, tolerances, plan, extremes, tradeoff, junit;
  int jobs = 0;
  size_t batch = 0;
  std::string schedule = "load";
  long run_job = -1;
  std::string run_jobs;
  bool resume = false, plan_only = false, compare_only = false, no_export_cache = false;
  std::string export_cache;
  double timeout = kDefaultToolTimeoutSeconds;
  BudgetOptions budget;
};

// The request the parsed arguments make (validate/validation/validate_run.h).
v::ValidateRequest requestOf(const Args& a, const std::vector<std::string>& renderer_files) {
  v::ValidateRequest r;
  r.inputs = a.inputs;
  r.output = a.dir;
  r.tolerances = a.tolerances;
  r.renderers = a.renderers;
  r.timeout_seconds = a.timeout;
  r.budget = a.budget.get();
  r.resume = a.resume;
  r.plan_only = a.plan_only;
  r.plan = a.plan;
  if (a.run_job >= 0) r.run_job = size_t(a.run_job);
  r.run_jobs = a.run_jobs;
  r.compare_only = a.compare_only;
  r.settings.workers = a.jobs > 0 ? a.jobs : defaultWorkers();
  r.settings.batch = a.batch;
  r.settings.by_load = a.schedule == "load";
  if (!a.extremes.empty()) r.sections.extremes = a.extremes;
  if (!a.tradeoff.empty()) r.sections.tradeoff = a.tradeoff;
  r.junit = a.junit;
  r.renderer_files = renderer_files;
  r.export_cache = !a.no_export_cache;
  r.export_cache_dir = a.export_cache;
  return r;
}
}  // namespace

void addValidateCommand(CLI::App& app, std::function<int()>& run) {
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "validate",
      "Render scenes with every renderer validate runs (default: " +
          renderers::joinNames(renderers::registry().everySceneIds()) +
          "; --renderers picks a subset, or adds a golden set), compare every pair with the declared "
          "tolerances, attribute each disagreement, and write results.json and report.html. Scenes made of "
          "model files also get the Blender-import check (blender-import: Blender imports the original files; "
          "its hit mask, depth and uv against the reference's).\n"
      "The work is one render job per scene and renderer, listed in OUT/jobs.json (outputs: "
      "OUT/<scene>/<renderer>.exr, .png and .job.json, the job's record), then one compare step. "
      "A plain run does it all here; --plan-only, --run-job and --compare-only do one step each, "
      "which is how scripts/slurm/submit.sh runs it on a Slurm cluster (docs/cluster.md).\n"
      "A renderer that declares it cannot express a scene is recorded as not expressible, with its "
      "reason, and the case is decided on the other pairs. A scene's \"renderers\" field that names "
      "reference takes golden (its stored images) too. A case with nothing compared (every other "
      "renderer left out or unable to express the scene) is NOT COMPARED, never a pass.\n"
      "Exit 0 when every case compared something and passes, 1 when any fails or compared nothing, "
      "2 on an error (bad scene, renderer missing or broken, a job not run). --plan-only exits 0 once the plan is written; "
      "--run-job exits 0 when its render succeeded, 2 when it failed; --run-jobs likewise for every "
      "job of its list.");
  cmd->add_option("scenes", args->inputs, defaultScenesHelp());
  cmd->add_option("-o,--output", args->dir,
                  "Output folder, e.g. results/<run>/ (required unless --plan is given)");
  cmd->add_option("--tolerances", args->tolerances, kToleranceFileHelp);
  cmd->add_option("--renderers", args->renderers,
                  "Render and compare only these renderers, comma-separated, at least two (default: " +
                      renderers::joinNames(v::jobRenderers()) +
                      "; xval renderers lists them). A golden set (golden, golden-NAME: stored images, "
                      "docs/golden-images.md) runs only when named. blender-import is the geometry check of model-file scenes "
                      "(its passes against the reference's, not an image pair): name it to keep it")
      ->delimiter(',');
  cmd->add_option("--jobs", args->jobs, "Cores to keep busy: renders in parallel, each case compared beside them as soon as its renders are done "
                  "(the longest jobs start first); with --compare-only, cases compared at once (default: the core count)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--batch", args->batch,
                  "Scenes per Blender process (blender, eevee: one persistent worker renders a batch; "
                  "0, the default: the scenes split evenly over the --jobs workers, at most 32 each; "
                  "1: one process per scene)");
  cmd->add_option("--schedule", args->schedule,
                  "load (default): a job takes the share of a core its renderer keeps busy, so POV-Ray, "
                  "which mostly waits, runs several jobs per core; count: --jobs jobs at once")
      ->check(CLI::IsMember({"load", "count"}));
  cmd->add_option("--timeout", args->timeout, "Seconds before an external renderer is killed")
      ->check(Seconds);
  addBudgetOptions(cmd, args->budget);
  cmd->add_option("--extremes", args->extremes,
                  "The folder of `xval extremes -o DIR` whose section the report shows (recorded in "
                  "results.json, relative to it; default: no extremes section)");
  cmd->add_option("--tradeoff", args->tradeoff,
                  "The folder of `xval tradeoff SCENE -o DIR` whose section the report shows (recorded in "
                  "results.json, relative to it; default: no trade-off section)");
  cmd->add_option("--junit", args->junit,
                  "Also write JUnit XML to this file after the compare step: one testcase per scene "
                  "and pair (classname = scene, name = pair) and per geometry check (name "
                  "\"reference-blender-import (geometry)\"), <failure> with the metrics and the "
                  "tolerance or bounds, <error> for a failed render (validate/report/junit_report.h)");
  auto* resume = cmd->add_flag(
      "--resume", args->resume,
      "Keep the renders of an earlier run into the same folder whose record says ok, whose "
      "inputs (scene file, image texture, renderer) are unchanged and whose EXR and PNG exist; "
      "render only the others (default: render everything)");
  auto* plan_only = cmd->add_flag(
      "--plan-only", args->plan_only,
      "Write OUT/jobs.json and render nothing; print the indices of the jobs to run (all, or "
      "with --resume those not done), one per line, on stdout");
  auto* plan = cmd->add_option("--plan", args->plan,
                               "A plan written by --plan-only (OUT/jobs.json); with --run-job or "
                               "--compare-only");
  auto* run_job = cmd->add_option("--run-job", args->run_job,
                                  "Run render job K (0-based index into the plan) and write its "
                                  "EXR, PNG and record, whether or not it was done before")
                      ->check(CLI::NonNegativeNumber);
  auto* run_jobs = cmd->add_option("--run-jobs", args->run_jobs,
                                   "Run the listed render jobs (plan indices and ranges, e.g. 0-3,7,9-11: "
                                   "a Slurm array task's batch) as a plain run renders them (--jobs, "
                                   "--batch, --schedule), whether or not they were done before");
  auto* compare_only = cmd->add_flag(
      "--compare-only", args->compare_only,
      "Compare and report from the plan's EXRs and job records (a job without a usable "
      "record is an error); render nothing");
  auto* export_cache = cmd->add_option(
      "--export-cache", args->export_cache,
      "Folder of the export cache: POV-Ray's and Blender's exports (and exporters' refusals) stored by a "
      "SHA-256 of the scene's files, its textures' and model files' bytes and this xval executable, so a "
      "scene exported for one run is copied, not exported, for the next; a partial or altered entry is "
      "exported again (default: $XDG_CACHE_HOME/xval/exports, else ~/.cache/xval/exports; at most 2 GiB, "
      "least recently used entries removed; only folders the cache made and marked are ever removed)");
  cmd->add_flag("--no-export-cache", args->no_export_cache, "Export every scene, read and store no cache")
      ->excludes(export_cache);
  run_job->needs(plan);
  compare_only->needs(plan);
  run_job->excludes(compare_only);
  run_jobs->needs(plan);
  run_jobs->excludes(compare_only)->excludes(run_job);
  plan->excludes(plan_only)->excludes(resume);
  auto renderer_files = addRendererFileOption(cmd);
  cmd->callback([args, &run, cmd, renderer_files]() {
    // Scheduling: for a plain run and --run-jobs.
    const bool schedule_given = cmd->count("--jobs") + cmd->count("--batch") + cmd->count("--schedule") > 0;
    // --compare-only takes --jobs (cases compared at once), not the others.
    const bool only_jobs_given = cmd->count("--jobs") > 0 && cmd->count("--batch") + cmd->count("--schedule") == 0;
    const bool local_options_given = cmd->count("--renderers") + cmd->count("--timeout") + cmd->count("--max-triangles") +
                                         cmd->count("--max-samples") + cmd->count("--max-memory-mb") +
                                         cmd->count("--allow-large") > 0;
    // With --plan, what a new run takes comes from the plan: given again,
    // it is an error, not ignored.
    const bool plan_step_options_wrong =
        !args->plan.empty() &&
        (!args->inputs.empty() || !args->dir.empty() || !args->tolerances.empty() || local_options_given ||
         (schedule_given && args->run_jobs.empty() && !(args->compare_only && only_jobs_given)));
    v::ValidateRequest r = requestOf(*args, *renderer_files);
    run = [r, plan_step_options_wrong]() -> int {
      try {
        if (plan_step_options_wrong)
          throw std::runtime_error("--plan " + r.plan +
                                   ": scenes, -o, --renderers, --tolerances, --timeout and the budget options come from the plan "
                                   "(and --jobs, --batch and --schedule are for a plain run or --run-jobs, --jobs also for --compare-only); give none of them");
        return v::run(r);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "xval validate: error: %s\n", e.what());
        return 2;
      }
    };
  });
}

}  // namespace xval::cli
