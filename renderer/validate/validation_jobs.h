// The work of `xval validate`, split into independent jobs so that a local
// run and a cluster run (Slurm job arrays, scripts/slurm/, docs/cluster.md)
// execute the same code:
//
//   plan     the render jobs (one scene x one renderer each: every
//            every-scene renderer of the registry, renderers/registry.h,
//            in its order), written to OUT/jobs.json; every output path
//            is fixed by the plan: OUT/<scene>/<renderer>.exr, .png and
//            the job's record OUT/<scene>/<renderer>.job.json
//   run job  renders one job and writes its EXR (the reference keeps its
//            diagnostics channels), its preview PNG and, last, its record
//            (seconds, render_seconds, error), each under a temporary name
//            and renamed: a record that says ok means the images are whole
//   compare  reads the plan, the records and the EXRs, compares every pair
//            (every unordered pair of those renderers, in registry order),
//            attributes each disagreement (renderers::attribute), and
//            writes results.json and report.html
//
// A local run is plan + every job in a thread pool + compare, so a local
// and a cluster run of the same scenes give the same verdicts and metrics
// by construction (only timings and provenance may differ).
//
// A job is done when its record says ok, the record's input hash equals
// the plan's (the scene file's bytes, its image texture's bytes and the
// renderer) and its EXR and PNG exist; resuming redoes only jobs that are
// not done.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "files/output_folder.h"
#include "scene/scene_budget.h"
#include "validate/report.h"
#include "scene/scene_loader.h"

namespace xval::validation {

struct RenderJob {
  size_t index = 0;             // position in the plan (the Slurm array index)
  std::string scene;            // the scene's name: its folder under the output folder
  std::string file;             // the scene file as given (shown in results.json)
  std::filesystem::path path;   // the scene file, absolute (read by the job)
  std::string renderer;         // a renderer id of the registry (renderers/registry.h)
  std::string input_hash;       // of what the render depends on (see above)
  // Outputs, relative to the plan's folder.
  std::string exr() const { return scene + "/" + renderer + ".exr"; }
  std::string png() const { return scene + "/" + renderer + ".png"; }
  std::string record() const { return scene + "/" + renderer + ".job.json"; }
};

struct Plan {
  std::filesystem::path dir;              // the output folder (holds jobs.json)
  std::string tolerances;                 // the tolerance file as given
  std::filesystem::path tolerances_path;  // the same, absolute
  double timeout_seconds = 0.0;           // for the external renderers
  Budget budget;                          // every scene is loaded with it (planning and every job)
  double created_unix = 0.0;              // when the plan was made (wall_seconds counts from it)
  std::vector<RenderJob> jobs;            // per scene, in scene order: one per renderer (jobRenderers())
};

// The renderers every scene goes through, in job order: the registry's
// every-scene renderers (for the built-in ones: reference, povray, blender).
std::vector<std::string> jobRenderers();

// The plan's file in an output folder.
std::filesystem::path planFile(const std::filesystem::path& dir);

// What xval validate writes or reads at the top of its output folder; no
// scene is named like one of them (sceneNameProblem, scene/scene_loader.h).
inline constexpr const auto& kOwnFiles = kReservedSceneNames;

// Removes the output folder's results.json and report.html (a new run, or a
// new compare step, starts with no verdict; the new ones are written last).
void removeVerdict(const Plan& plan);

// Scene files from files and folders (a folder: its *.json, sorted), loaded
// and checked (scene names unique and usable as folder names), one job per
// renderer of jobRenderers() each. Throws std::runtime_error / SceneError naming the file and field.
Plan makePlan(const std::vector<std::string>& inputs, const std::string& tolerances,
              const std::filesystem::path& dir, double timeout_seconds,
              const Budget& budget = Budget{});
void writePlan(const Plan& plan);  // to planFile(plan.dir), atomically
// Throws std::runtime_error naming the file, the field and what was expected.
Plan readPlan(const std::filesystem::path& file);

struct JobRecord {
  bool present = false;    // a readable record exists
  std::string input_hash;  // what it was rendered from
  double seconds = 0.0, render_seconds = -1.0;
  std::string error;       // empty when the render succeeded
  std::string problem;     // why the record cannot be used (missing, unreadable); empty when present
};

JobRecord readRecord(const Plan& plan, const RenderJob& job);
// True when the job need not run again; otherwise `why` says what is missing.
bool isDone(const Plan& plan, const RenderJob& job, std::string* why = nullptr);

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

// Compares every pair of every scene from the EXRs and records, writes
// each pair's difference EXR and heat map PNG, results.json (with the
// paper's Figure 1 verdicts, validate/paper_claims.h, and the `sections`
// folders) and report.html, prints the failing cases' next steps.
// Returns the exit status of `xval validate`: 0 all pass, 1 some case
// outside its tolerance, 2 an error (a render failed or a job has no
// usable record).
int compareAndReport(const Plan& plan, const ReportSections& sections = {});

}  // namespace xval::validation
