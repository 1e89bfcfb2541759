// results.json of `xval validate` (docs/results-schema.json): the cases the
// compare step made (compare_step.h), the provenance of the run, its wall
// time, the paper's Figure 1 verdicts (validate/paper_claims.h) and the
// report sections it names. The report is a view of this file alone
// (validate/report/report.h).
#pragma once

#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include "validate/validation/plan.h"

namespace xval::validation {

// The whole results file. `setting_files` are the files whose bytes define
// the run's settings (the tolerance file, then every scene file, in plan
// order): provenance.settings_hash is FNV-1a over their bytes and names.
nlohmann::ordered_json resultsJson(const Plan& plan, const nlohmann::ordered_json& cases,
                                   const std::vector<std::filesystem::path>& setting_files,
                                   const nlohmann::ordered_json& sections);

}  // namespace xval::validation
