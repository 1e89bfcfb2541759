// What `xval validate` prints on stderr for every case that does not pass
// (case_verdict.h): for a failing or error case, the crosscheck command
// that looks closer at each pair and how to accept a documented difference
// (a declared tolerance); for a case that compared nothing, why (the
// renderers left out, with their reasons).
#pragma once

#include <nlohmann/json.hpp>

#include "validate/validation/plan.h"

namespace xval::validation {

// `cases`: results.json's cases (results_file.h). The paths in the printed
// commands are single-quoted for a POSIX shell (' becomes '\''), so a
// pasted command cannot run anything a scene or folder name contains.
void printNextSteps(const Plan& plan, const nlohmann::ordered_json& cases);

}  // namespace xval::validation
