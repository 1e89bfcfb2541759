#include "povray/sdl.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace xval::pov {

std::string num(double v) {
  if (v == 0.0) return std::signbit(v) ? "-0" : "0";  // the sign of a zero normal component too
  char buf[40];
  // The shortest %.*g that round-trips.
  for (int prec = 6; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string vec(glm::dvec3 v) {
  std::string s = "<";
  return s.append(num(v.x)).append(", ").append(num(v.y)).append(", ").append(num(v.z)).append(">");
}
std::string vec(glm::dvec2 v) {
  std::string s = "<";
  return s.append(num(v.x)).append(", ").append(num(v.y)).append(">");
}

std::string commentSafe(const std::string& s) {
  std::string out;
  for (char c : s) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == ' ' || c == '_' || c == '.' || c == ',' || c == ':' || c == '+' || c == '=' ||
              c == '-';
    out += ok ? c : '_';
    if (out.size() >= 120) break;
  }
  return out;
}

}  // namespace xval::pov
