// Rounding a double to float32 so that the compiler cannot drop it.
//
// roundedToFloat(x) = double(float(x)): the float32 nearest to x (ties to
// even), widened back to double exactly. The exporters write float32
// (glTF buffers, POV-Ray's mesh2 vertices), so every attribute the
// reference renderer traces must be this value, bit for bit.
//
// Why not just write double(float(x)): the language makes that a rounding,
// but g++ 12.2 at -O2 compiles the loop `for (auto& p : v) p =
// glm::dvec3(glm::vec3(p));` to code that converts only p.z and leaves p.x
// and p.y untouched (its SLP vectoriser pairs the x and y narrowings with
// the widenings and folds the pair away; measured on this toolchain in the
// object code of tessellate(): cvtsd2ss/cvtss2sd for z only, and 0.1 stayed
// 0.1000000000000000055 instead of 0.100000001490116). A loop of scalar
// pairs is compiled to a bare `ret`. Nothing in the source is wrong; the
// rounding has to be made opaque.
//
// How: the float passes through an empty asm statement that takes it in a
// register and claims to modify it ("+x": an SSE register on x86-64, "+w":
// a SIMD/FP register on AArch64, otherwise "+m": memory). The compiler must
// therefore produce the float (cvtsd2ss) before the statement, and knows
// nothing about the value after it, so the widening (cvtss2sd) cannot be
// folded with the narrowing. The statement emits no instruction; the cost
// is the two conversions the code asked for. Compilers without GNU asm go
// through a volatile float (a store and a load) instead.
//
// tests/unit/float_rounding_test.cpp checks the result bit by bit against
// an integer model of round-to-nearest-even, on values the compiler cannot
// know, and tests/unit/traced_geometry_test.cpp checks every attribute the
// reference renderer traces against the exported files.
#pragma once

#include <glm/glm.hpp>

namespace xval {

// The float32 nearest to x; the conversion is never elided.
inline float nearestFloat(double x) {
  float f = static_cast<float>(x);
#if defined(__GNUC__) && defined(__x86_64__)
  asm("" : "+x"(f));
#elif defined(__GNUC__) && defined(__aarch64__)
  asm("" : "+w"(f));
#elif defined(__GNUC__)
  asm("" : "+m"(f));
#else
  volatile float opaque = f;
  f = opaque;
#endif
  return f;
}

// x rounded to the nearest float32, as a double (exact widening).
inline double roundedToFloat(double x) { return static_cast<double>(nearestFloat(x)); }

inline glm::dvec2 roundedToFloat(glm::dvec2 v) { return {roundedToFloat(v.x), roundedToFloat(v.y)}; }
inline glm::dvec3 roundedToFloat(glm::dvec3 v) {
  return {roundedToFloat(v.x), roundedToFloat(v.y), roundedToFloat(v.z)};
}

}  // namespace xval
