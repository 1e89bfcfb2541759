// The report's trade-off section: from the folder of `xval tradeoff SCENE
// -o DIR` (named in results.json or by `xval report --tradeoff DIR`),
// report.html shows its table (every configuration's knobs, frame time,
// errors against the converged reference, Pareto-optimal marked), the
// reference's convergence residuals and the Pareto plot
// (DIR/pareto.png, drawn by `xval tradeoff` with gnuplot).
#pragma once

#include <filesystem>
#include <string>

namespace xval {

// The section's HTML for folder/tradeoff.json (the folder of `xval tradeoff
// -o folder`), its image paths starting with `href` (the folder relative to
// the report), or "" when that file does not exist. Throws
// std::runtime_error naming the file and the field when it exists but is
// not a tradeoff file this version reads.
std::string tradeoffReportSection(const std::filesystem::path& folder, const std::string& href);

}  // namespace xval
