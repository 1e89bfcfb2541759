// report.html from a results.json of `xval validate`: a view of
// results.json and of the files it names, nothing else.
//
// What the report shows comes from results.json: the cases, their renders
// (each with the preview PNG it names; a failed render by its error text,
// never an <img> of a missing file) and pairs in the order of results.json
// `renderers` (the registry's: built-in renderers, then users' by name),
// the summary's row per case (its verdict, who deviates, its worst pair,
// and its pairs' verdicts opening onto a renderers x renderers matrix: as
// many columns for 15 pairs as for one), the
// pairs' heat maps (the PNG each pair names in `heat_map`, written by the
// compare step, which has the EXRs: image/heat_map.h writeHeatMapPng), the paper's Figure 1
// verdicts (`paper_claims`, computed by the compare step:
// validate/paper_claims.h), and the extremes and trade-off sections from
// the folders `sections` names (or the ones given to writeReport). It
// regenerates only what it can from results.json alone: the summary plot
// (p999.png, drawn by gnuplot through process/run_process.h; none when the
// run has no image pair) and the heat
// map's scale (heat_scale.png). A case's geometry checks (results.json
// geometry_checks, validate/results/geometry_checks.h) are a column of
// the summary, a count beside it, and a table of metrics against bounds in
// the case; a failing or erring check makes the case's verdict FAIL or
// ERROR. The page is validate/report/report_page.mustache (compiled into the
// binary), rendered with kainjow::mustache over a data view of the results'
// types (report_data.h, report_case.h, report_metrics.h); every string from
// the results is HTML-escaped, by the template or, in the fragments it
// inserts as they are (report_pixels.h, the extremes and trade-off
// sections), by the code that wrote them. The page checks on load that every image decoded and says
// so in its title ("xval report: N images OK" or "xval report: BROKEN
// ..."), which the report's test reads.
#pragma once

#include "validate/common/html_text.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "image/image.h"
#include "validate/results/results.h"

namespace xval {

// The folders of the extremes (`xval extremes -o DIR`: DIR/extremes.json)
// and trade-off (`xval tradeoff -o DIR`: DIR/tradeoff.json) results.
// Unset: the one results.json names in `sections`, if any.
struct ReportSections {
  std::optional<std::filesystem::path> extremes, tradeoff;
};

// results.json's `sections`: each folder given, relative to `results_dir`
// (so the report folder can move as a whole). Throws std::runtime_error when
// a folder has no extremes.json / tradeoff.json.
nlohmann::ordered_json sectionsJson(const ReportSections& sections, const std::filesystem::path& results_dir);

// Throws std::runtime_error (file, what is wrong) on bad input or when
// gnuplot is missing or fails.
void writeReport(const std::filesystem::path& results_json, const std::filesystem::path& html,
                 const ReportSections& sections = {});

// What the summary shows of a pair of results.json (not HTML-escaped): its
// verdict in capitals, then, when it fails, the short form of the first
// criterion it fails ("FAIL fraction 99.81% < 99.9%": results.json
// "failed", image/pair_failure.h), else its max unexplained error in
// 1/65535 ("PASS 3.76"); "ERROR" for a pair not compared.
std::string pairSummary(const results::Pair& pair);

}  // namespace xval
