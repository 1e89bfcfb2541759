// xval golden update / xval golden check: storing a renderer's images of a
// scene set as its golden images (golden/golden_set.h) and checking a fresh
// render against them.
//
// update renders every scene with the renderer (the reference renderer:
// the scene's own spp on the exact double-precision path, diagnostics on)
// and stores the image and its manifest entry, replacing an earlier one.
//
// check renders every scene again and compares the fresh image with the
// stored one by the project's one comparison (image/compare.h), held to the
// tolerance of the golden set's id (`golden` for the reference renderer's,
// `golden-NAME` for NAME's) found as for every comparison
// (validate/tolerances.h: the tolerance file's default unless the scene
// declares one for that id). A scene fails when it is outside the
// tolerance, has no stored image, was rendered with other settings, or its
// file changed since it was stored; each failure prints the command that
// accepts the fresh render as the new golden image.
//
// check is not `validate --renderers reference,golden` (validation::run):
// validate has no float path for the reference, does not refuse a stored
// image made with other settings, makes a changed scene a render error
// (exit 2) rather than a FAIL, and needs an output folder; the reasons are
// in docs/golden-images.md ("check beside validate").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/export_common.h"
#include "scene_file/scene_budget.h"

namespace xval::validation {

struct GoldenRequest {
  std::vector<std::string> inputs;  // scene files or folders (scene_file/scene_set.h)
  std::string renderer;             // a registry id; not a golden set itself
  std::string tolerances;           // check only; empty: found by the one rule
  // check only, the reference renderer only: "float" renders the fast path
  // and compares it with the stored images of the exact double path (the
  // settings must then agree except for the precision).
  std::string precision = "double";
  double timeout_seconds = kDefaultToolTimeoutSeconds;
  Budget budget;
};

// Returns 0. Throws on the first error (nothing half-stored: each image and
// the manifest are written atomically, the manifest after the images).
int goldenUpdate(const GoldenRequest& request);

// Returns 0 when every scene matches its golden image, 1 when any does not
// (each printed on stdout with its reason and the accepting command).
// Throws on an error of the renderer or a malformed manifest.
int goldenCheck(const GoldenRequest& request);

}  // namespace xval::validation
