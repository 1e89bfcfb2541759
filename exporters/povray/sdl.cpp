#include "povray/sdl.h"

#include <cstdio>
#include <cstdlib>

namespace xval::pov {

std::string num(double v) {
  if (v == 0.0) return "0";
  char buf[40];
  // The shortest %.*g that round-trips.
  for (int prec = 6; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

std::string vec(glm::dvec3 v) { return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">"; }
std::string vec(glm::dvec2 v) { return "<" + num(v.x) + ", " + num(v.y) + ">"; }

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
