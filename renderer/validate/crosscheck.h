// xval crosscheck: one scene rendered by the reference renderer and by
// one other renderer of the registry (renderers/registry.h), compared with
// the tolerance declared for that case.
//
// Writes DIR/reference.exr, DIR/<renderer>.exr (the renderer's work folder
// DIR/<renderer>.work made fresh first), DIR/diff.exr and, last,
// DIR/metrics.json (the comparison's metrics, the tolerance and its
// reason, the seconds of each render); prints a one-line verdict on
// stdout. The folder is locked for the run (files/output_folder.h).
//
// A renderer of geometry passes (Renderer::geometry_passes: blender-import)
// is compared instead with the reference's passes of the same scene
// (validate/geometry_check.h, its own bounds): DIR/reference-passes.exr,
// DIR/<renderer>.exr and DIR/metrics.json (that comparison's metrics).
//
// When the renderer declares that it cannot express the scene
// (Renderer::cannot_express, the exporter's refusal), nothing is rendered:
// metrics.json says "not_expressible" with the reason, the verdict line
// says NOT EXPRESSIBLE, and the exit status is 0 (no pair to compare; not
// a failure). A missing, failing or hanging renderer stays an error.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "common/export_common.h"
#include "scene_file/scene_budget.h"
#include "validate/results/results.h"

namespace xval::validation {

struct CrosscheckRequest {
  std::string scene_file;  // the scene, loaded with `budget`
  std::string renderer;    // a registry id other than the reference's
  std::string dir;         // the output folder
  // The tolerance file; empty: found by the one rule (validate/tolerances.h:
  // the nearest tolerances.json at or above the scene, else the toolkit's).
  std::string tolerances;
  double timeout_seconds = kDefaultToolTimeoutSeconds;
  Budget budget;
};

// Returns 0 when within the tolerance or not expressible, 1 when outside
// it. Throws on an error (a bad scene or tolerance file, a scene whose
// `renderers` does not name the renderer, a renderer missing, failing or
// timing out: never a pass).
int crosscheck(const CrosscheckRequest& request);

// One crosscheck run in the form of a results.json (one case, one pair
// "reference-<renderer>") as the results types (validate/results/results.h;
// the case has no verdict), for the JUnit writer (validate/junit_report.h):
// with `error` empty, the verdict and metrics of DIR/metrics.json (which
// crosscheck writes last, so a run that did not finish has none), or its
// not_expressible (a pair not compared: JUnit <skipped>); else a pair that
// is that error. The case is named by the scene's name, or by
// the scene file's stem when the scene could not be loaded. A renderer of
// geometry passes (blender-import) gives no pair but the case's
// geometry_checks record, as validate writes it
// (validate/results/geometry_checks.h).
results::Results crosscheckAsResults(const CrosscheckRequest& request, const std::string& error);

}  // namespace xval::validation
