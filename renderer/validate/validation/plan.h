// The work of `xval validate`, split into independent jobs so that a local
// run and a cluster run (Slurm job arrays, scripts/slurm/, docs/cluster.md)
// execute the same code:
//
//   plan     (plan.h) the render jobs (one scene x one renderer each: the
//            run's renderers, validate --renderers or every renderer
//            validate runs by default, Registry::validateIds: the
//            every-scene renderers and the geometry checks, in registry order,
//            less those the scene's `renderers` field leaves out, recorded
//            with the reason), written to OUT/jobs.json; every output path
//            is fixed by the plan: OUT/<scene>/<renderer>.exr, .png and
//            the job's record OUT/<scene>/<renderer>.job.json
//   run job  (run_job.h, job_record.h) renders one job and writes its EXR (the reference keeps its
//            diagnostics channels), its preview PNG and, last, its record
//            (seconds, render_seconds, error), each under a temporary name
//            and renamed: a record that says ok means the images are whole
//   compare  (compare_step.h, results_file.h, next_steps.h) reads the plan, the records and the EXRs, compares every pair
//            (every unordered pair of those renderers, in registry order),
//            attributes each disagreement (renderers::attribute), and
//            writes results.json and report.html
//
// A geometry check's job (Renderer::geometry_passes: blender-import) writes
// the renderer's geometry passes as its EXR and, beside them, the
// reference renderer's passes of the same scene,
// OUT/<scene>/<renderer>.reference-passes.exr (RenderJob::
// reference_passes): the two sides of that one comparison, so the compare
// step only compares (validate/results/geometry_checks.h) and the check
// is done, resumed or kept as one job. They are made in the check's job
// rather than in the reference's so that the reference job's outputs do
// not depend on which renderers the run has, and the check needs no other
// job: the passes cost one ray per pixel (under a second) beside Blender's
// import (seconds).
//
// A local run is plan + every job in a thread pool + compare, so a local
// and a cluster run of the same scenes give the same verdicts and metrics
// by construction (only timings and provenance may differ).
//
// A job is done when its record says ok, the record's input hash equals
// the plan's (inputHash: the scene file's bytes, its textures' and model
// files' bytes, the renderer and, for a renderer defined by a file, that
// file's bytes) and its EXR and PNG exist, or when its record says the renderer
// declared the scene not expressible (Renderer::cannot_express: a verdict,
// with no images); resuming redoes only jobs that are not done.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "files/output_folder.h"
#include "scene_file/scene_budget.h"
#include "scene_file/scene_loader.h"

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
  // A geometry check's job (see above) only: the reference's passes.
  std::string reference_passes() const { return scene + "/" + renderer + ".reference-passes.exr"; }
};

// A renderer of the run that a scene is not meant for (its `renderers`
// field), and why: no job, no pair.
struct LeftOut {
  std::string renderer;
  std::string reason;
};

// One scene of the plan; its jobs are adjacent in Plan::jobs.
struct PlannedScene {
  std::string name;             // the scene's name: its folder under the output folder
  std::string file;             // the scene file as given
  std::filesystem::path path;   // the scene file, absolute
  std::vector<LeftOut> left_out;
  bool kept = false;            // an earlier run's case this run keeps (plan_update.h): not rendered again
};

// A renderer of the run defined by a file (renderers/renderer_file.h; for
// golden-NAME, NAME's): the plan records it so that every job of the plan
// (a resumed run, a Slurm array task) renders with the same definition.
struct RendererFile {
  std::string name;             // the renderer's id
  std::filesystem::path path;   // the definition file, absolute
  std::string sha256;           // of its bytes when the plan was made
};

struct Plan {
  std::filesystem::path dir;              // the output folder (holds jobs.json)
  std::string tolerances;                 // the tolerance file as given
  std::filesystem::path tolerances_path;  // the same, absolute
  double timeout_seconds = 0.0;           // for the external renderers
  Budget budget;                          // every scene is loaded with it (planning and every job)
  double created_unix = 0.0;              // when the plan was made (wall_seconds counts from it)
  std::vector<std::string> renderers;     // the run's renderers, in registry order (at least two)
  std::vector<RendererFile> renderer_files;  // those of them defined by a file (see RendererFile)
  std::vector<PlannedScene> scenes;       // in scene order
  std::vector<RenderJob> jobs;            // per scene, in scene order: one per renderer of `renderers`
                                          // the scene is meant for, in that order
};

// The renderers every scene goes through by default, in job order:
// Registry::validateIds (for the built-in ones: reference, povray,
// blender, blender-import, eevee, gl).
std::vector<std::string> jobRenderers();

// Whether `validate --renderers` takes the renderer only when it is named:
// a golden set (`golden`, `golden-NAME`; renderers/golden.cpp), which a
// scene set may not have, or a restricted renderer (a native tier,
// Renderer::restricted). Without --renderers, validate takes a restricted
// renderer when a scene names it; either way it renders only the scenes
// whose `renderers` field names it.
bool runsWhenNamed(const std::string& id);

// A left-out renderer nobody needs told about: a restricted renderer left
// out of a scene that does not name it. The plan records it (its jobs
// follow from it); the console and results.json do not.
bool leftOutUnsaid(const LeftOut& l);

// The run's renderers from `validate --renderers` (empty: jobRenderers()),
// in registry order: jobRenderers() and, when named, the golden sets
// (`golden`, `golden-NAME`, also spelled `golden:NAME`). Throws
// std::runtime_error for any other name (listing them), a name given
// twice, or fewer than two.
std::vector<std::string> runRenderers(const std::vector<std::string>& names);

// A crosscheck's renderers (validate/validation/crosscheck.h): the reference and
// `renderer`, any renderer of the registry but the reference (a golden set
// also spelled golden:NAME; renderers validate leaves out, such as
// blender-native, too). Throws std::runtime_error for an unknown id
// (listing them) or the reference itself.
std::vector<std::string> crosscheckRenderers(const std::string& renderer);

// A plan's renderers as given: runRenderers' of them, or a crosscheck's
// pair (crosscheckRenderers); throws as runRenderers does for any other.
std::vector<std::string> planRenderers(const std::vector<std::string>& names);

// What a plan does with a renderer a scene is not meant for (its
// `renderers` field): validate leaves it out of that case (recorded with
// the reason); a crosscheck, whose one renderer it is, refuses the scene.
enum class NotMeantFor { LeaveOut, Refuse };

// The jobs of plan.scenes[k], as indices into plan.jobs (adjacent).
std::vector<size_t> sceneJobs(const Plan& plan, size_t k);

// The plan's file in an output folder.
std::filesystem::path planFile(const std::filesystem::path& dir);

// What xval validate writes or reads at the top of its output folder; no
// scene is named like one of them (sceneNameProblem, scene_file/scene_loader.h).
inline constexpr const auto& kOwnFiles = kReservedSceneNames;

// Removes the output folder's results.json and report.html (a new run, or a
// new compare step, starts with no verdict; the new ones are written last).
void removeVerdict(const Plan& plan);

// Scene files from files and folders (scene_file/scene_set.h: a folder's *.json,
// sorted, less those that are not scenes, each said on stderr), loaded
// and checked (scene names unique and usable as folder names), one job per
// renderer of `renderers` (planRenderers) the scene is meant for; the others
// are its left_out, each said on stderr (with NotMeantFor::Refuse, an error:
// "FILE: renderers: the scene is meant for A and B only, not C"). Throws
// std::runtime_error / SceneError naming the file and field.
Plan makePlan(const std::vector<std::string>& inputs, const std::string& tolerances,
              const std::filesystem::path& dir, double timeout_seconds,
              const Budget& budget = Budget{}, const std::vector<std::string>& renderers = jobRenderers(),
              NotMeantFor not_meant_for = NotMeantFor::LeaveOut);
void writePlan(const Plan& plan);  // to planFile(plan.dir), atomically
// Throws std::runtime_error naming the file, the field and what was expected.
// The plan's renderer files are added to the process's registry (those not
// in it yet) before its renderers are read; a definition file that is
// missing or whose SHA-256 is not the recorded one is an error (the jobs
// would render with another renderer than the plan's).
Plan readPlan(const std::filesystem::path& file);

// What a render depends on, as a hash: the renderer (for one defined by a
// file, that file's bytes), the scene file's bytes, its image textures'
// bytes and every file of its model files (Model::files: an OBJ's mtl and
// images, a glTF's buffers) (the plan's and a record's input_hash).
std::string inputHash(const Scene& scene, const std::filesystem::path& scene_file, const std::string& renderer);

// The bytes those hashes cover, piece by piece (the scene file's, its image
// textures', and each model file's name and bytes), for inputHash and
// exportInputsKey alike.
void forEachInput(const Scene& scene, const std::filesystem::path& scene_file,
                  const std::function<void(const std::string&)>& add);

// What an export of the scene depends on besides the exporter, as a
// SHA-256: the scene file's absolute path and forEachInput's pieces, each
// with its length (renderers/export_cache.h: the inputs key).
std::string exportInputsKey(const Scene& scene, const std::filesystem::path& scene_file);

}  // namespace xval::validation
