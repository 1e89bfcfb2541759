// The report's "Extremes" section (report_section.cpp documents its
// layout), from FOLDER/extremes.json as run.h writes it.
#pragma once

#include <filesystem>
#include <string>

namespace xval::extremes {

// "0123456789ab" from `git describe --always --dirty --abbrev=40` output,
// with " plus uncommitted changes" for a dirty tree.
std::string shortCommit(const std::string& described);

// The report's section (validate/report/report.cpp calls it): HTML for
// folder/extremes.json (the folder of `xval extremes -o folder`, as
// results.json or `xval report --extremes` names it), with its tables and
// maps, whose paths start with `href` (the folder relative to the report);
// "" when there is no such file. Throws std::runtime_error on a malformed
// file.
std::string reportSection(const std::filesystem::path& folder, const std::string& href);

}  // namespace xval::extremes
