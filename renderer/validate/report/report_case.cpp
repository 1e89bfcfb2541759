// A case's section of report.html (validate/report/report_case.h).
#include "validate/report/report_case.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "image/metric_criteria.h"
#include "image/pair_failure.h"
#include "image/pixel_classes.h"
#include "render/geometry_passes.h"
#include "text/number_text.h"
#include "validate/report/report.h"
#include "validate/report/report_data.h"
#include "validate/report/report_metrics.h"
#include "validate/report/report_pixels.h"

namespace xval {

namespace fs = std::filesystem;
namespace mu = kainjow::mustache;
using namespace page;

namespace {

// A small number in two significant digits ("3.3e-06", "0.84").
std::string twoDigits(double v) { return fmt::format("{:.2g}", v); }

// A pixel class's entry (its key, image/pixel_classes.h) of a pair's
// per-class counts or maxima; null when the file has none for it.
template <class T>
const T* ofClass(const results::Named<T>& per_class, const std::string& key) {
  for (const auto& [k, v] : per_class)
    if (k == key) return &v;
  return nullptr;
}

// Whether a case's render is a geometry check's: a picture of its passes
// (render/geometry_passes.h passesPreview), not a render.
bool isGeometryCheck(const results::Case& c, const std::string& renderer) {
  for (const results::GeometryCheck& g : c.geometry_checks)
    if (g.renderer == renderer) return true;
  return false;
}

std::string geometryCheckCaption() {
  return std::string("not a render: its geometry passes (") + kPassesPreviewLegend +
         "), compared with the reference's passes of our loaded triangles (the geometry check below)";
}

// A case's geometry checks: per check, each metric beside the bound it is
// held to (validate/geometry_check.h), the verdict and its reason. None
// when the case has none; else one: checks (name, not_compared: none or
// one of class and text, compared: none or one of the verdict's
// check_class and check_text, the numbers as text and reason).
mu::data geometryChecksTable(const results::Case& c) {
  mu::data table = list();
  if (c.geometry_checks.empty()) return table;
  mu::data checks = list();
  for (const results::GeometryCheck& g : c.geometry_checks) {
    mu::data row;
    row.set("name", checkName(g));
    mu::data not_compared = list(), compared = list();
    if (!g.metrics) {
      const bool nx = g.verdict == results::PairVerdict::NotExpressible;
      mu::data d;
      d.set("class", nx ? "nexp" : "err");
      d.set("text", (nx ? "not expressible: " : "error: ") + g.reason.value_or(""));
      not_compared << d;
    } else {
      const results::GeometryCheckMetrics& m = *g.metrics;  // a compared check has both (results/results.h)
      const results::GeometryCheckBounds& b = *g.bounds;
      const double covered = double(m.covered);
      mu::data d;
      d.set("check_class", verdictClass(checkVerdict(g)));
      d.set("check_text", upperCase(checkVerdict(g)));
      d.set("covered", std::to_string(m.covered));
      d.set("off", std::to_string(m.mask_disagree - m.mask_disagree_silhouette));
      d.set("silhouette", std::to_string(m.mask_disagree_silhouette));
      d.set("silhouette_bound", std::to_string(static_cast<long long>(std::floor(b.max_silhouette_fraction * covered))));
      d.set("depth", twoDigits(m.max_depth_rel));
      d.set("depth_bound", twoDigits(b.max_depth_rel));
      d.set("depth_all", twoDigits(m.max_depth_rel_all));
      d.set("uv_compared", std::to_string(m.uv_compared));
      d.set("uv", twoDigits(m.max_uv));
      d.set("uv_bound", twoDigits(b.max_uv));
      d.set("uv_all", twoDigits(m.max_uv_all));
      d.set("edge_over", std::to_string(m.edge_over));
      d.set("edge_bound", std::to_string(static_cast<long long>(std::floor(b.max_edge_fraction * covered))));
      d.set("reason", maybe(g.reason));
      compared << d;
    }
    row.set("not_compared", not_compared);
    row.set("compared", compared);
    checks << row;
  }
  mu::data t;
  t.set("checks", checks);
  table << t;
  return table;
}

// A render's figure: renderer, not_expressible (its reason, or none), else
// image (the file's name, when renderHasImage) or no_image (why not),
// seconds, render_seconds, geometry_caption (each none or one).
mu::data renderFigure(const results::Case& c, const std::string& renderer, const results::Render& rr,
                      const fs::path& dir) {
  mu::data f;
  f.set("renderer", renderer);
  f.set("not_expressible", maybe(rr.not_expressible));
  // A failed render shows its error where its image would be: no <img> of
  // a file that is not there.
  const bool has_image = renderHasImage(rr, dir);
  f.set("image", maybe(has_image ? rr.image : std::nullopt));
  f.set("no_image", maybe(has_image ? std::nullopt
                                       : std::optional<std::string>(
                                             rr.error ? "error: " + *rr.error
                                                      : "no image: " + rr.image.value_or("(none named)") +
                                                            " (named in results.json) is missing")));
  f.set("seconds", fixed(rr.seconds, 2));
  f.set("render_seconds", maybe(rr.render_seconds ? std::optional<std::string>(fixed(*rr.render_seconds, 2))
                                                     : std::nullopt));
  f.set("geometry_caption", maybe(isGeometryCheck(c, renderer) ? std::optional<std::string>(geometryCheckCaption())
                                                                  : std::nullopt));
  return f;
}

// A pair's row of the case's table: pair, not_compared (none, or one of
// class, colspan, text) and metrics (none, or one: the verdict's
// pair_class and pair_text, the numbers as text, over_tolerance: per pixel
// class count and class_max).
mu::data pairRow(const results::Pair& p) {
  mu::data row;
  row.set("pair", p.pair);
  mu::data not_compared = list(), metrics = list();
  const std::string colspan = std::to_string(9 + kPixelClassCount);
  if (p.verdict == results::PairVerdict::NotExpressible || !p.metrics) {
    const bool nexp = p.verdict == results::PairVerdict::NotExpressible;
    mu::data d;
    d.set("class", nexp ? "nexp" : "err");
    d.set("colspan", colspan);
    d.set("text", nexp ? "not expressible, not compared: " + p.not_expressible.value_or("") : p.error.value_or("error"));
    not_compared << d;
  } else {
    const results::PairMetrics& m = *p.metrics;
    mu::data d;
    d.set("pair_class", verdictClass(pairVerdict(p)));
    d.set("pair_text", upperCase(pairVerdict(p)));
    d.set("max_unexplained", fixed(m.max_unexplained_16bit, 2));
    d.set("cap", fixed(m.tolerance.max_unexplained_16bit, 0));
    d.set("max", fixed(m.max_abs_16bit, 2));
    d.set("p999", fixed(m.p999_abs_16bit, 2));
    d.set("rmse", fixed(m.rmse_16bit, 3));
    d.set("psnr", m.psnr_db ? fixed(*m.psnr_db, 1) : std::string("inf"));
    d.set("within", fixed(100.0 * m.fraction_within, 3));
    d.set("tolerance", significant(m.tolerance.max_abs_16bit));
    d.set("fraction", significant(100.0 * m.tolerance.fraction));
    d.set("metric_criteria", maybe(m.tolerance.metrics.empty() ? std::nullopt
                                                                : std::optional<std::string>(metricCriteriaText(m.tolerance.metrics))));
    d.set("masks_off", std::to_string(m.mask_disagree));
    d.set("masks_explained", std::to_string(m.mask_disagree_explained));
    mu::data classes = list();
    for (const PixelClassInfo& k : kPixelClasses) {
      const long long* count = ofClass(m.over_tolerance, k.key);
      const std::optional<double>* max = ofClass(m.over_tolerance_max_16bit, k.key);
      mu::data cell;
      cell.set("count", count ? std::to_string(*count) : std::string("n/a"));
      cell.set("class_max", maybe(max && count && *count > 0 ? std::optional<std::string>(fixed(*max, 1))
                                                                : std::nullopt));
      classes << cell;
    }
    d.set("over_tolerance", classes);
    metrics << d;
  }
  row.set("not_compared", not_compared);
  row.set("metrics", metrics);
  return row;
}

// A case's section: scene, verdict_class, verdict_text, attribution,
// reproduce (none or one), left_out, warnings, renders (renderFigure, in
// the run's order), pair_rows (pairRow), notes (pair, label, text: why each
// failing pair fails, then each declared tolerance's reason), and the
// metric_table (report_metrics.h), check_table (geometryChecksTable) and
// the fragment case_pixels (report_pixels.h).
}  // namespace

mu::data caseSection(const results::Case& c, const std::vector<std::string>& run_renderers, const fs::path& dir) {
  const std::string verdict = caseVerdict(c);
  mu::data d;
  d.set("scene", c.scene);
  d.set("verdict_class", verdictClass(verdict));
  d.set("verdict_text", upperCase(verdict));
  d.set("attribution", c.attribution);
  // The command is the compare step's (validate/validation/next_steps.h
  // reproduceCommand: with the run's renderers, renderer files and
  // tolerance file); results.json files written before it had none: no
  // command rather than one that would not run as the case ran.
  d.set("reproduce", maybe(c.reproduce));
  d.set("left_out", members(c.left_out, "renderer", "why"));
  // The scene's warnings (lint/scene_lint.h): beside the verdict, not in it.
  mu::data warnings = list();
  for (const results::Warning& w : c.warnings) {
    mu::data l;
    l.set("subject", w.subject);
    l.set("message", w.message);
    l.set("code", w.code);
    warnings << l;
  }
  d.set("warnings", warnings);
  mu::data renders = list();
  for (const std::string& rid : run_renderers)
    if (const results::Render* rr = c.render(rid)) renders << renderFigure(c, rid, *rr, dir);
  d.set("renders", renders);
  d.set("case_pixels", casePixels(c, dir));
  mu::data pair_rows = list();
  for (const results::Pair& p : c.pairs) pair_rows << pairRow(p);
  d.set("pair_rows", pair_rows);
  // Every metric of the table (image/metric_table.h), a column each.
  d.set("metric_table", pairMetricsTable(c.pairs));
  d.set("check_table", geometryChecksTable(c));
  // Why each failing pair fails: every criterion, with its numbers.
  mu::data notes = list();
  auto note = [&notes](const std::string& pair, const char* label, const std::string& text) {
    mu::data n;
    n.set("pair", pair);
    n.set("label", label);
    n.set("text", text);
    notes << n;
  };
  for (const results::Pair& p : c.pairs) {
    if (p.verdict == results::PairVerdict::Finding)
      note(p.pair, "finding", p.finding->renderer + ": " + p.finding->why + " Measured: p99.9 " +
                                  fixed(p.metrics->p999_abs_16bit, 2) + ", max " + fixed(p.metrics->max_abs_16bit, 2) +
                                  " (1/65535); outside the tolerance as declared: " + failedText(p.failed));
    else if (p.finding && p.failed.empty())
      note(p.pair, "finding no longer holds", p.finding->renderer + " agrees within the tolerance, but the scene "
                                              "declares: " + p.finding->why);
    else if (!p.failed.empty())
      note(p.pair, "fails", failedText(p.failed));
  }
  for (const results::Pair& p : c.pairs)
    if (p.metrics && !p.metrics->tolerance_reason.empty()) note(p.pair, "tolerance", p.metrics->tolerance_reason);
  d.set("notes", notes);
  return d;
}

}  // namespace xval
