// Formatting numbers, vectors and safe comments for POV-Ray SDL.
#pragma once

#include <glm/glm.hpp>

#include <string>

namespace xval::pov {

// The first of "%.6g" .. "%.17g" that reads back as the same double
// (so at least six significant digits, at most seventeen).
std::string num(double v);
// <x, y, z>
std::string vec(glm::dvec3 v);
std::string vec(glm::dvec2 v);
// A user string made safe to put in an SDL comment line: only
// [A-Za-z0-9 _.,:+=-] survive; everything else becomes '_', and the
// length is capped. Scene strings never go anywhere else in the SDL.
std::string commentSafe(const std::string& s);

}  // namespace xval::pov
