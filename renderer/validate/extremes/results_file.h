// The extremes results (run.h): one case's measurements as the JSON of
// DIR/extremes.json, and the Markdown table of DIR/extremes.md.
//
// extremes.json (format "xval-extremes/1"): provenance {date, machine,
// git_commit, compiler, command, renderers}, size, wall_seconds, totals
// {cases, reference_nonfinite_pixels, external_errors}, cases [...]; each
// case: name, group, what, scene (relative to DIR), size [w, h], rerun,
// reference {double, float: {seconds, image, nonfinite {final, raw}}},
// float_vs_double (image/compare.h's metricsJson of the float render
// against the double one, plus map), preview, external {<renderer>:
// {status, seconds, render_seconds (when the renderer reports it), and
// when ok: nonfinite, metrics (metricsJson plus map), preview; else
// reason}}.
//
// The Markdown table: per case the NaN/Inf counts (final / raw) and, for
// float and each external renderer (run.h: externalRenderers(), a column
// each, named by the registry), "max / p99.9 (mask disagreements)"
// in 1/65535 with 2 decimals, "n/a" for a value that is null, or the
// external renderer's status.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "image/compare.h"
#include "validate/common/provenance.h"
#include "validate/extremes/matrix.h"
#include "validate/extremes/measure.h"

namespace xval::extremes {

// One external render's outcome.
struct External {
  std::string status;  // "ok", "not renderable", "error"
  std::string reason;  // for anything but ok
  Image image;
  double seconds = 0.0, render_seconds = -1.0;  // render_seconds: -1 when not reported
};

// "scenes/<name>.json" etc. are relative to the run's folder; dir_text is
// that folder as given (for the rerun line).
nlohmann::ordered_json caseJson(const Case& c, const std::string& dir_text, int width, int height,
                                const ReferenceRender& dbl, const ReferenceRender& flt,
                                const CompareMetrics& float_vs_double);
// metricsJson(m) with "map": the heat map's path relative to the run's folder.
nlohmann::ordered_json metricsWithMap(const CompareMetrics& m, const std::string& map);

nlohmann::ordered_json provenanceJson(const Provenance& p, const std::string& command,
                                      const std::vector<std::string>& renderers);

std::string markdownTable(const nlohmann::ordered_json& results);

}  // namespace xval::extremes
