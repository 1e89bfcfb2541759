#include "povray/sdl.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace xval::pov {

namespace {
// Significant digits of the shortest decimal that reads back as v
// (std::to_chars without a precision: "d.ddde+x").
int shortestDigits(double v) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::scientific);
  int digits = 0;
  for (const char* c = buf; c < r.ptr && *c != 'e'; ++c) digits += (*c >= '0' && *c <= '9');
  return digits;
}
}  // namespace

// The text is the first of "%.6g", "%.7g", ..., "%.17g" that reads back as
// v. No precision below P, the digit count of the shortest decimal that
// reads back (shortestDigits), can: %.{p}g prints a p-digit decimal. So
// the search starts at max(6, P), where it nearly always ends at once
// (%.{P}g prints the p-digit decimal nearest to v, which is the shortest
// one unless v is a power of two whose shortest decimal lies above it in
// the wider upper half of its rounding interval). This costs one printf
// and one parse per number instead of up to twelve of each; the text is
// the same (PovSdl.NumIsTheFirstPrecisionThatRoundTrips).
std::string num(double v) {
  if (v == 0.0) return std::signbit(v) ? "-0" : "0";  // the sign of a zero normal component too
  char buf[40];
  const int first = std::isfinite(v) ? std::max(6, shortestDigits(v)) : 6;
  for (int prec = first; prec <= 17; ++prec) {
    // std::to_chars with a precision prints what printf's "%.*g" prints in
    // the C locale (the standard defines it so), without printf's cost.
    const auto w = std::to_chars(buf, buf + sizeof buf - 1, v, std::chars_format::general, prec);
    *w.ptr = '\0';
    const int n = int(w.ptr - buf);
    double back = 0.0;
    const auto r = std::from_chars(buf, buf + n, back);
    if (r.ec == std::errc() && r.ptr == buf + n && back == v) break;
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
