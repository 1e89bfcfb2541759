// xval crosscheck: one scene rendered by the reference renderer and by
// one other renderer of the registry (renderers/registry.h), compared with
// the tolerance declared for that case.
//
// It is `xval validate` of that one scene with those two renderers
// (validation::run with ValidateRequest::crosscheck_renderer): the same
// plan, jobs, compare step and files in DIR (jobs.json, DIR/<scene>/ with
// the two renders, their records and the heat maps, results.json,
// report.html; the folder locked for the run, files/output_folder.h). What
// a crosscheck adds is read from the typed results (results/results.h),
// never from JSON by key: the one-line verdict on stdout and
// DIR/metrics.json, the pair (or geometry check) as results.json has it
// with the scene, the renderer, the tolerance file and the seconds of the
// two renders.
//
// Unlike validate, any renderer of the registry but the reference may be
// named (blender-native, a golden set, a renderer file's), a scene whose
// `renderers` field does not name it is an error, not left out, and an
// earlier run in DIR (another crosscheck's, of any scene or renderer) is
// replaced, its cases not kept (validate/validation/plan_update.h).
//
// A renderer of geometry passes (Renderer::geometry_passes: blender-import)
// is validate's geometry check (validate/geometry_check.h, its own bounds),
// not an image pair.
//
// When the renderer declares that it cannot express the scene
// (Renderer::cannot_express, the exporter's refusal), it renders nothing:
// metrics.json says "not_expressible" with the reason, the verdict line
// says NOT EXPRESSIBLE, and the exit status is 0 (no pair to compare; not
// a failure). A missing, failing or hanging renderer stays an error.
#pragma once

#include <string>
#include <vector>

#include "common/export_common.h"
#include "scene_file/scene_budget.h"
#include "validate/results/results.h"

namespace xval::validation {

struct CrosscheckRequest {
  std::string scene_file;  // the scene, loaded with `budget`
  std::string renderer;    // a registry id other than the reference's (golden:NAME too)
  std::string dir;         // the output folder
  // The tolerance file; empty: found by the one rule (validate/tolerances.h:
  // the nearest tolerances.json at or above the scene, else the toolkit's).
  std::string tolerances;
  double timeout_seconds = kDefaultToolTimeoutSeconds;
  Budget budget;
  std::vector<std::string> renderer_files;  // renderer definition files to add first
};

// Returns 0 when within the tolerance or not expressible, 1 when outside
// it, 2 when a render failed (said on stderr as "xval crosscheck: error:
// ..."). Throws on an error before any render (a bad scene or tolerance
// file, a scene whose `renderers` does not name the renderer, an unknown
// renderer). `results` is set to the run's one case (without a case
// verdict: a crosscheck's verdict is its pair's) as soon as the compare
// step has written it, for the JUnit writer (validate/report/junit_report.h).
int crosscheck(const CrosscheckRequest& request, results::Results& results);

// The results of a crosscheck that stopped with `error` before its compare
// step: one case (named by the scene file's stem) whose pair
// "reference-<renderer>", or geometry check for a renderer of geometry
// passes, is that error.
results::Results crosscheckError(const CrosscheckRequest& request, const std::string& error);

}  // namespace xval::validation
