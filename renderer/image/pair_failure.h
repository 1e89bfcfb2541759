// Why a pair of renders fails its tolerance (image/compare.h
// Tolerance::passes), criterion by criterion, with the numbers: what the
// report's cells, the console and JUnit say instead of a bare maximum
// (a pair that fails on the fraction within tolerance with a max
// unexplained error of 3.76/65535 is not "FAIL 3.76").
//
// The criteria, in this fixed order (each listed when it fails):
//   nothing_covered  no pixel covered by both images
//   mask             mask disagreements no edge explains
//   unexplained_cap  an unexplained pixel over the cap (max_unexplained)
//   fraction         fewer covered pixels within the tolerance than `fraction`
//   metric:ID        a declared metric criterion (image/metric_criteria.h)
//                    that does not hold, one per metric, in table order
// Errors are fractions of full scale, written in 1/65535.
//
// A failure is "hard" when a criterion other than the fraction fails
// (a metric criterion too: it was declared to hold) (the
// images differ where nothing explains it), "soft" when only the fraction
// does (many small differences, each under the cap: rounding): who
// deviates (renderers/registry.h attribute) weighs them differently.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/compare.h"
#include "image/metric_table.h"

namespace xval {

struct PairFailure {
  bool operator==(const PairFailure&) const = default;
  std::string key;    // nothing_covered, mask, unexplained_cap, fraction or metric:ID
  std::string text;   // "fraction within tolerance 99.81% < 99.9% (8 of 4769 pixels outside)"
  std::string brief;  // for a table cell: "99.81% < 99.9% within"
};

// Every criterion of `t` that `m` fails, in the order above; empty exactly
// when passes(m, t) (image/metric_criteria.h).
std::vector<PairFailure> failedCriteria(const PairMeasures& m, const Tolerance& t);
// The same from the pixel measures, for a tolerance without metric
// criteria (empty exactly when t.passes(m)); throws std::logic_error for
// one with them.
std::vector<PairFailure> failedCriteria(const CompareMetrics& m, const Tolerance& t);

// Whether the failures are of the fraction alone (non-empty, every one
// "fraction"): a soft failure.
bool failsOnlyOnFraction(const std::vector<PairFailure>& failed);

// results.json's pair "failed": [{"key", "text", "brief"}, ...] (empty: the
// pair passes).
nlohmann::json failedJson(const std::vector<PairFailure>& failed);

// The failures of results.json's "failed" (nlohmann::json or
// ordered_json); throws std::runtime_error "WHERE: ..." when it is not a
// list of objects with "key", "text" and "brief" strings.
template <class Json>
std::vector<PairFailure> failedFromJson(const Json& failed, const std::string& where) {
  if (!failed.is_array()) throw std::runtime_error(where + ": expected a list of failed criteria");
  std::vector<PairFailure> out;
  for (const auto& f : failed) {
    for (const char* k : {"key", "text", "brief"})
      if (!f.is_object() || !f.contains(k) || !f[k].is_string())
        throw std::runtime_error(where + ": each entry needs a \"" + k + "\" string");
    out.push_back({f["key"].template get<std::string>(), f["text"].template get<std::string>(),
                   f["brief"].template get<std::string>()});
  }
  return out;
}

// Every failure's text, joined by "; ".
std::string failedText(const std::vector<PairFailure>& failed);

}  // namespace xval
