#include "povray/pov_log.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace xval {

namespace {

// The figure of "<label>: ... (S seconds)" on `line`, or -1 when the line
// is another label's or its bracketed figure is not a finite S >= 0.
double bracketedSeconds(std::string_view line, std::string_view label) {
  const size_t start = line.find_first_not_of(" \t");
  if (start == std::string_view::npos || line.substr(start, label.size()) != label) return -1.0;
  const size_t open = line.rfind('(');
  if (open == std::string_view::npos || open < start + label.size()) return -1.0;
  const std::string_view rest = line.substr(open + 1);
  double s = -1.0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), s);
  if (ec != std::errc() || std::string_view(end, rest.data() + rest.size()).rfind(" seconds)", 0) != 0)
    return -1.0;
  return std::isfinite(s) && s >= 0.0 ? s : -1.0;
}

}  // namespace

PovLogTimes povLogTimes(std::string_view text) {
  PovLogTimes t;
  struct Field {
    std::string_view label;
    double PovLogTimes::*value;
  };
  const Field fields[] = {{"Parse Time:", &PovLogTimes::parse_seconds},
                          {"Bounding Time:", &PovLogTimes::bounding_seconds},
                          {"Photon Time:", &PovLogTimes::photon_seconds},
                          {"Trace Time:", &PovLogTimes::trace_seconds}};
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view line = text.substr(pos, nl - pos);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    for (const Field& f : fields) {
      const size_t start = line.find_first_not_of(" \t");
      if (start != std::string_view::npos && line.substr(start, f.label.size()) == f.label)
        t.*f.value = bracketedSeconds(line, f.label);  // a later unreadable one makes it absent
    }
    pos = nl + 1;
  }
  return t;
}

PovLogTimes povLogTimesOfFile(const std::filesystem::path& log) {
  std::ifstream in(log, std::ios::binary);
  if (!in) return {};
  std::ostringstream s;
  s << in.rdbuf();
  return povLogTimes(s.str());
}

}  // namespace xval
