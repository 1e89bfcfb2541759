// One case's section of report.html (validate/report/report.h) as data of the
// page's template (validate/report/report_page.mustache): its verdict,
// attribution and command to reproduce it, the renderers left out, its
// warnings, its renders (a failed one by its error, never an <img> of a
// missing file), its pixels (report_pixels.h, an escaped fragment), the
// pairs' table with the counts and maxima per pixel class, the metrics
// table (report_metrics.h), the geometry checks' table and why each
// failing pair fails.
#pragma once

#include <filesystem>
#include <kainjow/mustache.hpp>
#include <string>
#include <vector>

#include "validate/results/results.h"

namespace xval {

// `run_renderers`: the run's renderers in their one order (its renders
// follow it); `dir`: the folder of results.json and the files it names.
kainjow::mustache::data caseSection(const results::Case& c, const std::vector<std::string>& run_renderers,
                                    const std::filesystem::path& dir);

}  // namespace xval
