// report.html from a results.json of `xval validate`.
//
// Reads only results.json and the images `validate` wrote beside it; writes
// report.html, a heat map PNG per pair (heat_<pair>.png, the largest
// channel difference per pixel on a logarithmic colour scale from 1/65535
// to 4096/65535, grey where neither render covers the pixel), the scale
// (heat_scale.png) and the summary plot (p999.png, drawn by gnuplot).
// Every string from the results is HTML-escaped. The page checks on load
// that every image decoded and says so in its title ("xval report: N
// images OK" or "xval report: BROKEN ..."), which the report's test reads.
#pragma once

#include <filesystem>
#include <string>

namespace xval {

// Throws std::runtime_error (file, what is wrong) on bad input or when
// gnuplot is missing or fails.
void writeReport(const std::filesystem::path& results_json, const std::filesystem::path& html);

std::string htmlEscape(const std::string& s);

}  // namespace xval
