// A pixel row or column from a floating-point screen coordinate, without
// undefined behaviour: converting a double outside int's range (a vertex
// projected from just in front of the eye lands at 1e20 px) or a NaN to
// int is undefined in C++, so the value is clamped first, in double.
#pragma once

namespace xval {

// v clamped to [lo, hi], then converted; NaN gives lo. For the integral
// values of floor() and ceil() the conversion is exact.
inline int clampedIndex(double v, int lo, int hi) {
  if (!(v >= double(lo))) return lo;  // below, or NaN
  if (v >= double(hi)) return hi;
  return int(v);
}

}  // namespace xval
