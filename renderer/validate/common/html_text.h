// Text inside HTML: the report's one escaping (the page's template,
// validate/report/report.cpp, escapes every {{key}} with it; the report
// sections of extremes and tradeoff, and report_pixels, with it too).
#pragma once

#include <string>

namespace xval {

// & < > " ' as entities (&#39; for '), everything else as is: safe in
// element text and in double- or single-quoted attribute values.
std::string htmlEscape(const std::string& s);

}  // namespace xval
