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
// When the renderer declares that it cannot express the scene
// (Renderer::cannot_express, the exporter's refusal), nothing is rendered:
// metrics.json says "not_expressible" with the reason, the verdict line
// says NOT EXPRESSIBLE, and the exit status is 0 (no pair to compare; not
// a failure). A missing, failing or hanging renderer stays an error.
#pragma once

#include <string>

#include "common/export_common.h"
#include "scene/scene_budget.h"

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

}  // namespace xval::validation
