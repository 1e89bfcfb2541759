// The report's trade-off section: when the report's folder holds
// tradeoff/tradeoff.json (written by `xval tradeoff SCENE -o DIR/tradeoff`),
// report.html shows its table (every configuration's knobs, frame time,
// errors against the converged reference, Pareto-optimal marked), the
// reference's convergence residuals and the Pareto plot
// (tradeoff/pareto.png, drawn by `xval tradeoff` with gnuplot).
#pragma once

#include <filesystem>
#include <string>

namespace xval {

// The section's HTML, or "" when report_dir/tradeoff/tradeoff.json does not
// exist. Throws std::runtime_error naming the file and the field when it
// exists but is not a tradeoff file this version reads.
std::string tradeoffReportSection(const std::filesystem::path& report_dir);

}  // namespace xval
