// `xval extremes`: runs the extremes matrix (matrix.h, docs/extremes.md).
//
// Writes every case's scene into DIR/scenes/, renders it with the
// reference renderer in double and in float (one case after another, all
// threads), then with the external renderers (`jobs` renders at a time,
// process/job_pool.h; each killed after `timeout` seconds), compares each
// with the double render (measure.h) and writes (results_file.h):
//   DIR/extremes.json       per case: scene file, NaN/Inf counts of both
//                           reference renders, float-vs-double metrics,
//                           per external renderer its status and metrics
//   DIR/extremes.md         the same as a Markdown table (for docs)
//   DIR/<case>/double.exr, float.exr, <renderer>.exr (ignored by git),
//   DIR/<case>/*.png        8-bit previews and heat maps (heat_float.png:
//                           float vs double; heat_<renderer>.png: that
//                           renderer vs double), DIR/heat_scale.png
// Progress on stderr.
//
// ExtremesRun (defaults): dir (required); size = 160 pixels per side of
// every case; only = "" (all cases; else comma-separated names);
// renderers = externalRenderers() (empty: reference renderer only);
// jobs = 0 (the hardware thread count); timeout = 600 s; threads = 0
// (every hardware thread, for the reference renders); command: the
// command line recorded in the provenance.
//
// Returns the exit status: 0 when the reference renderer has no NaN/Inf in
// any case and precision (final or raw channels) and every external render
// that was attempted either succeeded or was refused by its exporter with a
// reason; 1 when the reference renderer produced a NaN or Inf; 2 when an
// external renderer failed, timed out or is missing (an error, never a
// pass). Throws on any other error (a case that cannot be written or
// loaded, an unknown case or renderer, an unwritable folder).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/export_common.h"

namespace xval::extremes {

// The external renderers the matrix can use, in registry order
// (renderers/registry.h): every renderer that renders every scene, but the
// reference (today povray, blender).
std::vector<std::string> externalRenderers();

struct ExtremesRun {
  std::filesystem::path dir;
  int size = 160;
  std::string only;
  std::vector<std::string> renderers = externalRenderers();
  int jobs = 0, threads = 0;
  double timeout = kDefaultToolTimeoutSeconds;
  std::string command;
};

int runExtremes(const ExtremesRun& run);

}  // namespace xval::extremes
