// results.json of `xval validate` (docs/results-schema.json) as C++ types,
// with its one reader and its one writer: the report (validate/report/report.h),
// JUnit (validate/report/junit_report.h) and the compare step read and write the
// file through these, not through string keys.
//
// What is modelled: the run (format, provenance, wall time, renderers,
// cases, sections), each case (scene, file, renders, pairs, left-out
// renderers, warnings, attribution, deviating renderers, reproduce
// command, verdict, pass, geometry checks), each render, each pair (its
// verdict, error or refusal, heat and bound maps, pass, failed criteria,
// metrics, crops), each geometry check (its metrics and bounds), the
// colour statistics, the paper's claims, and of the pair metrics those the
// report and JUnit show (sizes, errors, mask disagreements, tolerance,
// tolerance reason, the metric table's values). What is kept as JSON, read
// and written back unchanged (never dropped): a pair's classification, the
// rest of its metrics (histogram, worst pixels, precision models, ...), and in every modelled object any member the
// types do not name (`rest`: in a file the schema accepts, only those
// metrics; in a crosscheck's metrics.json, its own fields too).
//
// Verdicts are stored, never derived by a reader: a case's (CaseVerdict,
// validation/case_verdict.h) and a pair's (PairVerdict below), both decided
// by the compare step (validation/compare_step.cpp) and written to the
// file. A pair of a file written before pairs carried "verdict" (the
// committed results/validation/results.json, hand-written fixtures) gets
// the one its fields imply; a stored verdict its fields contradict is an
// error naming the field.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/pair_failure.h"
#include "scene/metric_criterion.h"
#include "validate/results/case_verdict.h"

namespace xval::results {

using Json = nlohmann::ordered_json;

// A pair's verdict (results.json cases[].pairs[].verdict), and a geometry
// check's (cases[].geometry_checks[].verdict): the same four words.
//   pass / fail       compared, within / outside the tolerance (bounds);
//   error             not compared: a render failed or the images cannot
//                     be compared;
//   not_expressible   not compared: a renderer cannot express the scene (a
//                     verdict, not an error);
//   finding           compared, outside the tolerance, as the scene declares
//                     for one of its renderers (Scene::findings: its
//                     built-in model differs from the scene's): the known
//                     difference, measured; no failure. A pair with a
//                     finding that is within the tolerance is a fail (the
//                     finding no longer holds). Pairs only.
enum class PairVerdict { Pass, Fail, Error, NotExpressible, Finding };

// "pass", "fail", "error", "not_expressible", "finding"
const char* pairVerdictName(PairVerdict v);
// Throws std::runtime_error "WHERE: "word": expected ..." for another word.
PairVerdict parsePairVerdict(const std::string& word, const std::string& where);

// Key-value members in file order (provenance, left_out, a case's renders).
template <class T>
using Named = std::vector<std::pair<std::string, T>>;

struct Render {
  double seconds = 0;
  std::optional<double> render_seconds, process_seconds, parse_seconds;
  std::optional<std::string> image, error, not_expressible;
  Json rest = Json::object();
  bool operator==(const Render&) const = default;
};

struct PairTolerance {
  double max_abs_16bit = 0, fraction = 0, max_unexplained_16bit = 0;
  bool exclude_backfacing = false;
  // The declared metric criteria (image/metric_criteria.h; "metrics", absent
  // when none and in files written before them).
  std::vector<MetricCriterion> metrics;
  bool operator==(const PairTolerance&) const = default;
};

// A compared pair's metrics (docs/results-schema.json definitions.metrics).
struct PairMetrics {
  long long width = 0, height = 0;
  double max_abs_16bit = 0, p999_abs_16bit = 0, rmse_16bit = 0, fraction_within = 0;
  std::optional<double> psnr_db;                // none: the images are equal (infinite)
  long long mask_disagree = 0, mask_disagree_explained = 0;
  std::optional<double> max_unexplained_16bit;  // none: infinite
  // Over-tolerance pixels: "total", then a count per pixel class by its key
  // (image/pixel_classes.h), in file order; and per class the largest error
  // among them (none: infinite; 0: no such pixel).
  Named<long long> over_tolerance;
  Named<std::optional<double>> over_tolerance_max_16bit;
  PairTolerance tolerance;
  std::string tolerance_reason;                 // empty: the default tolerance
  // The metric table's values by id (image/metric_table.h), in file order;
  // a value none is not finite. No `values` at all (files before the table): none.
  std::optional<Named<std::optional<double>>> values;
  Json rest = Json::object();  // every other metric, as written
  bool operator==(const PairMetrics&) const = default;
};

// A pixel the report shows with crops around it (validate/pixel_crops.h);
// paths relative to results.json.
struct ShownPixel {
  long long x = 0, y = 0;
  std::optional<double> error_16bit;  // none: infinite
  std::string pixel_class;            // "class": a key of image/pixel_classes.h
  long long window_x = 0, window_y = 0, window_width = 0, window_height = 0;
  std::string heat_map;
  Named<std::string> renders;         // renderer -> crop
  bool operator==(const ShownPixel&) const = default;
};

struct PairCrops {
  std::optional<ShownPixel> worst_unexplained, worst_explained;
  bool operator==(const PairCrops&) const = default;
};

// The scene's finding a compared pair is held to (Scene::findings): the
// renderer that declares it and why. It holds when the pair is outside its
// tolerance (`pass` false).
struct PairFinding {
  std::string renderer, why;
  bool operator==(const PairFinding&) const = default;
};

struct Pair {
  std::string pair;  // "<a>-<b>"
  PairVerdict verdict = PairVerdict::Error;
  std::optional<PairFinding> finding;
  std::optional<std::string> error, not_expressible, heat_map, bound_map;
  std::optional<bool> pass;            // compared pairs only
  std::vector<PairFailure> failed;     // the criteria it fails (compared pairs)
  std::optional<PairMetrics> metrics;  // compared pairs only
  std::optional<PairCrops> crops;
  Json classification;                 // null: none
  Json rest = Json::object();
  bool operator==(const Pair&) const = default;
};

// A compared geometry check's counts and maxima, and the bounds it is held
// to (validate/geometry_check.h; docs/results-schema.json
// definitions.geometry_check).
struct GeometryCheckMetrics {
  long long covered = 0, mask_disagree = 0, mask_disagree_silhouette = 0, compared = 0;
  double max_depth_rel = 0, max_depth_rel_all = 0;
  long long uv_compared = 0;
  double max_uv = 0, max_uv_all = 0;
  long long depth_edges = 0, edge_over = 0;
  bool operator==(const GeometryCheckMetrics&) const = default;
};

struct GeometryCheckBounds {
  double max_silhouette_fraction = 0, max_depth_rel = 0, max_uv = 0, max_edge_fraction = 0;
  std::string reason;
  bool operator==(const GeometryCheckBounds&) const = default;
};

struct GeometryCheck {
  std::string renderer, against;
  PairVerdict verdict = PairVerdict::Error;
  std::optional<std::string> reason;
  // A compared check (pass, fail) has both; one not compared neither.
  std::optional<GeometryCheckMetrics> metrics;
  std::optional<GeometryCheckBounds> bounds;
  Json rest = Json::object();
  bool operator==(const GeometryCheck&) const = default;
};

struct Warning {
  std::string code, subject, message;
  bool operator==(const Warning&) const = default;
};

// The reference image's colour statistics (validate/colour_stats.h).
struct ColourStats {
  long long lit_pixels = 0;
  double mean_chroma = 0, mean_albedo_chroma = 0, grey_fraction = 0, hue_error_deg = 0;
  bool operator==(const ColourStats&) const = default;
};

// The paper's Figure 1 claims as judged (validate/paper_claims.h).
struct PaperClaim {
  std::string claim, condition, measured;
  bool holds = false;
  bool operator==(const PaperClaim&) const = default;
};

struct PaperClaims {
  std::vector<std::string> scenes;
  std::vector<PaperClaim> claims;
  bool operator==(const PaperClaims&) const = default;
};

struct Case {
  std::string scene, file;
  std::optional<std::string> reproduce;
  Named<Render> renders;
  Named<std::string> left_out;  // renderer -> why
  std::vector<Warning> warnings;
  std::vector<Pair> pairs;
  std::optional<ColourStats> colour_stats;
  std::vector<GeometryCheck> geometry_checks;
  std::string attribution;
  std::vector<std::string> deviating;
  // Every results.json case has one; a crosscheck's single case
  // (validation::crosscheck: its verdict is the pair's) has none.
  std::optional<validation::CaseVerdict> verdict;
  bool pass = false;
  Json rest = Json::object();
  bool operator==(const Case&) const = default;

  const Render* render(const std::string& id) const;
  const Pair* findPair(const std::string& key) const;
};

struct Results {
  std::string format = "xval-results/1";
  Named<std::string> provenance;
  double wall_seconds = 0;
  std::vector<std::string> renderers;
  std::vector<Case> cases;
  std::optional<PaperClaims> paper_claims;
  std::optional<std::string> extremes_section, tradeoff_section;  // `sections`
  Json rest = Json::object();
  bool operator==(const Results&) const = default;
};

// results.json read as the report reads it (a key given twice, nesting too
// deep: refused), checked against docs/results-schema.json
// (validate/results/results_shape.h), then typed. Throws std::runtime_error
// "FILE: FIELD: ..." naming the file and the field.
Results readResults(const std::filesystem::path& file);

// The typed form of already-parsed JSON, without the schema check (a
// crosscheck's results, tests): errors "WHERE: FIELD: ..." or
// "WHERE: cases[0]: no "pairs" field", where WHERE is `where`.
Results resultsFromJson(const Json& j, const std::string& where);
// One pair of a case, as resultsFromJson reads each (tests of one pair).
Pair pairFromJson(const Json& j, const std::string& where);

// The one writer: the JSON of `r` (modelled fields in the order the compare
// step writes them, then each object's `rest`), and the file (strings that
// are no UTF-8 written with U+FFFD, atomically).
Json toJson(const Results& r);
// One pair, one geometry check, as toJson writes each (crosscheck's metrics.json).
Json toJson(const Pair& p);
Json toJson(const GeometryCheck& g);
void writeResults(const std::filesystem::path& file, const Results& r);

}  // namespace xval::results
