// xval validate's run, step by step (validate/validation/validate_run.h).
#include "validate/validation/validate_run.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "files/atomic_write.h"
#include "files/output_folder.h"
#include "renderers/export_cache.h"
#include "renderers/registry.h"
#include "renderers/renderer_file.h"
#include "scene/json_reader.h"
#include "scene_file/scene_loader.h"
#include "validate/report/junit_report.h"
#include "validate/results/results.h"
#include "validate/tolerances.h"
#include "validate/validation/compare_step.h"
#include "validate/validation/image_handoff.h"
#include "validate/validation/plan.h"
#include "validate/validation/plan_update.h"

namespace xval::validation {

namespace {

namespace fs = std::filesystem;

// After the compare step: the JUnit XML of its results.json, when asked
// for. The compare step's exit status stands; a JUnit file that cannot be
// written is an error.
int withJunit(const Plan& plan, int status, const std::string& junit) {
  if (junit.empty()) return status;
  const fs::path results = plan.dir / "results.json";
  const fs::path name = plan.dir.lexically_normal().filename();
  // As the report reads it (validate/results/results.h).
  writeFileAtomically(junit, junitXml(xval::results::readResults(results),
                                      name.empty() ? std::string("xval validate") : name.string()));
  std::fprintf(stderr, "xval validate: wrote %s\n", junit.c_str());
  return status;
}

bool hasSections(const ReportSections& s) { return s.extremes || s.tradeoff; }

// --run-jobs: the listed jobs as a plain run renders them.
int runListedJobs(const Plan& plan, const ValidateRequest& r) {
  const std::vector<size_t> list = parseJobList(r.run_jobs, plan.jobs.size());
  const std::vector<JobRecord> recs = runJobs(plan, list, r.settings);
  const size_t failed =
      size_t(std::count_if(recs.begin(), recs.end(), [](const JobRecord& rec) { return !rec.error.empty(); }));
  std::fprintf(stderr, "xval validate: jobs %s: %zu of %zu ok, %zu failed (errors in their records)\n",
               r.run_jobs.c_str(), list.size() - failed, list.size(), failed);
  return failed == 0 ? 0 : 2;
}

// --run-job K: that one job, its outcome said on stderr.
int runOneJob(const Plan& plan, const ValidateRequest& r) {
  if (*r.run_job >= plan.jobs.size())
    throw std::runtime_error("--run-job " + std::to_string(*r.run_job) + ": " + r.plan + " has jobs 0 to " +
                             std::to_string(plan.jobs.size() - 1));
  const RenderJob& job = plan.jobs[*r.run_job];
  const JobRecord rec = runJob(plan, job);
  std::fprintf(stderr, "xval validate: job %zu %s %s: %s in %.2f s; wrote %s\n", job.index, job.scene.c_str(),
               job.renderer.c_str(),
               !rec.error.empty() ? "ERROR" : !rec.not_expressible.empty() ? "not expressible" : "ok", rec.seconds,
               (plan.dir / job.record()).c_str());
  if (!rec.error.empty()) std::fprintf(stderr, "  %s\n", rec.error.c_str());
  if (!rec.not_expressible.empty()) std::fprintf(stderr, "  %s\n", rec.not_expressible.c_str());
  for (const std::string& n : rec.notes) std::fprintf(stderr, "  note: %s\n", n.c_str());
  return rec.error.empty() ? 0 : 2;
}

// One step of a plan written before (--plan).
int runPlanStep(const ValidateRequest& r) {
  if (!r.run_job && r.run_jobs.empty() && !r.compare_only)
    throw std::runtime_error("--plan " + r.plan + ": say what to do: --run-job K, --run-jobs LIST or --compare-only");
  const Plan plan = readPlan(r.plan);
  // Jobs of one plan run side by side (a cluster array): they share the
  // folder; a plain run, --plan-only or --compare-only excludes every
  // other writer.
  const FolderLock folder_lock(plan.dir, r.compare_only ? FolderLock::Mode::Exclusive : FolderLock::Mode::Shared,
                               "xval validate");
  if (r.compare_only) return withJunit(plan, compareAndReport(plan, r.sections, r.settings.workers), r.junit);
  if (hasSections(r.sections))
    throw std::runtime_error("--extremes and --tradeoff are for the compare step (a plain run or "
                             "--compare-only), not --run-job");
  return r.run_jobs.empty() ? runOneJob(plan, r) : runListedJobs(plan, r);
}

// A new run: plan (keeping the folder's other cases), then render and
// compare, or with plan_only list the jobs to run.
int runNew(const ValidateRequest& r) {
  if (r.output.empty()) throw std::runtime_error("-o OUTPUT is required (or --plan with --run-job / --compare-only)");
  if (r.plan_only && hasSections(r.sections))
    throw std::runtime_error("--extremes and --tradeoff are for the compare step (a plain run or "
                             "--compare-only), not --plan-only");
  sectionsJson(r.sections, r.output);  // a folder with no results fails before any render
  const std::vector<std::string> inputs = r.inputs.empty() ? std::vector<std::string>{toolkitSceneSet().string()}
                                                           : r.inputs;
  const bool crosscheck = !r.crosscheck_renderer.empty();
  Plan plan = makePlan(inputs, r.tolerances, r.output, r.timeout_seconds, r.budget,
                       crosscheck ? crosscheckRenderers(r.crosscheck_renderer) : runRenderers(r.renderers),
                       crosscheck ? NotMeantFor::Refuse : NotMeantFor::LeaveOut);
  fs::create_directories(plan.dir);
  const FolderLock folder_lock(plan.dir, FolderLock::Mode::Exclusive, "xval validate");
  // The folder's other cases are kept (validate/validation/plan_update.h);
  // a crosscheck's folder holds that one crosscheck: an earlier run there,
  // of any scene and renderers, is replaced, as a crosscheck's files were.
  if (const std::optional<Plan> earlier = crosscheck ? std::nullopt : earlierPlan(plan)) {
    const PlanUpdate update = keepEarlierScenes(plan, *earlier);
    for (const std::string& d : update.dropped) std::fprintf(stderr, "xval validate: earlier case %s\n", d.c_str());
    if (update.kept)
      std::fprintf(stderr, "xval validate: keeping %zu earlier cases of %s (compared again, not rendered)\n",
                   update.kept, plan.dir.c_str());
  }
  // A new run: the old verdict must not pass for this run's, even if this
  // run is killed before it writes its own.
  removeVerdict(plan);
  writePlan(plan);
  const std::vector<size_t> todo = withoutKept(plan, jobsToRun(plan, r.resume));
  if (r.plan_only) {
    for (size_t k : todo) std::printf("%zu\n", k);
    std::fprintf(stderr, "xval validate: wrote %s: %zu jobs (%zu scenes, renderers %s), %zu to run\n",
                 planFile(plan.dir).c_str(), plan.jobs.size(), plan.scenes.size(),
                 renderers::joinNames(plan.renderers).c_str(), todo.size());
    return 0;
  }
  if (r.resume && todo.size() < plan.jobs.size())
    std::fprintf(stderr, "xval validate: --resume: %zu of %zu jobs done before, %zu to run\n",
                 plan.jobs.size() - todo.size(), plan.jobs.size(), todo.size());
  // Each case is compared as soon as its jobs are done, in the same pool as
  // the renders (run_job.h AfterCase); the verdict is written once every
  // case is compared (compare_step.h CaseComparer). The jobs hand their
  // images to the compares (image_handoff.h).
  ImageHandoff images;
  CaseComparer comparer(plan, r.sections, &images);
  const AfterCase compare_case{[&comparer](size_t k) { comparer.compare(k); }, 1.0, &images};
  runJobs(plan, todo, r.settings, &compare_case);
  return withJunit(plan, comparer.finish(), r.junit);
}

}  // namespace

int run(const ValidateRequest& r) {
  if (!r.plan.empty() && !r.renderer_files.empty())
    throw std::runtime_error("--plan " + r.plan +
                             ": the renderer files come from the plan (recorded with their SHA-256 when it was "
                             "made); give no --renderer-file");
  renderers::registerRendererFiles(r.renderer_files);
  if (r.export_cache)
    renderers::setExportCache({r.export_cache_dir.empty() ? renderers::defaultExportCacheFolder() : r.export_cache_dir,
                               renderers::kDefaultExportCacheBytes});
  return r.plan.empty() ? runNew(r) : runPlanStep(r);
}

}  // namespace xval::validation
