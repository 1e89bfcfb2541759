// roundedToFloat (geometry/float_rounding.h) against an integer model of
// round-to-nearest-even, on values the compiler cannot know: random bit
// patterns from std::random_device, and edge cases read through volatile.
// The checks are integer comparisons of std::bit_cast bits, so no
// floating-point folding in the test itself can hide a missing rounding.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include "geometry/float_rounding.h"

using namespace xval;

namespace {

// Rounds the bits of a double to the 24-bit significand of float32, ties to
// even, by integer arithmetic: drop the low 29 of the 52 fraction bits and
// add one unit of the 29th when they exceed half of it (or equal half and
// the kept part is odd). A carry into the exponent is the right result.
// Valid when the result is a normal float32 (the callers keep to that).
std::uint64_t modelBits(std::uint64_t b) {
  const std::uint64_t sign = b & (std::uint64_t(1) << 63), mag = b & ~sign;
  const std::uint64_t unit = std::uint64_t(1) << 29, low = mag & (unit - 1), half = unit >> 1;
  std::uint64_t kept = mag - low;
  if (low > half || (low == half && (kept & unit))) kept += unit;
  return sign | kept;
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// Random doubles with exponents in [-100, 100] (normal as float32 after
// rounding) and all 52 fraction bits random.
std::vector<double> randomDoubles(size_t n) {
  std::random_device rd;
  std::mt19937_64 gen((std::uint64_t(rd()) << 32) | rd());
  std::uniform_int_distribution<int> exponent(-100, 100);
  std::vector<double> out;
  for (size_t i = 0; i < n; ++i) {
    const std::uint64_t fraction = gen() & ((std::uint64_t(1) << 52) - 1);
    const std::uint64_t sign = gen() & 1;
    const std::uint64_t e = std::uint64_t(exponent(gen) + 1023);
    out.push_back(std::bit_cast<double>(sign << 63 | e << 52 | fraction));
  }
  return out;
}

}  // namespace

TEST(FloatRounding, RandomDoublesRoundToNearestEven) {
  const std::vector<double> v = randomDoubles(200000);
  std::vector<double> r(v.size());
  for (size_t i = 0; i < v.size(); ++i) r[i] = roundedToFloat(v[i]);
  size_t wrong = 0;
  for (size_t i = 0; i < v.size(); ++i)
    if (bits(r[i]) != modelBits(bits(v[i])) && ++wrong <= 5)
      ADD_FAILURE() << "roundedToFloat(" << std::hexfloat << v[i] << ") = " << r[i]
                    << ", expected " << std::bit_cast<double>(modelBits(bits(v[i])));
  EXPECT_EQ(wrong, 0u) << "of " << v.size();
}

// The shape of the loop that g++ 12.2 -O2 compiled away for x and y: a
// whole vector of dvec3 (and dvec2) rounded in place.
TEST(FloatRounding, VectorsRoundEveryComponentInALoop) {
  const std::vector<double> v = randomDoubles(3 * 4096);
  std::vector<glm::dvec3> p(4096);
  std::vector<glm::dvec2> uv(4096);
  for (size_t i = 0; i < p.size(); ++i) p[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
  for (size_t i = 0; i < uv.size(); ++i) uv[i] = {v[3 * i + 1], v[3 * i + 2]};
  for (auto& x : p) x = roundedToFloat(x);
  for (auto& x : uv) x = roundedToFloat(x);
  size_t wrong = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      if (bits(p[i][k]) != modelBits(bits(v[3 * i + k])) && ++wrong <= 5)
        ADD_FAILURE() << "dvec3 component " << k << " of " << i << ": " << std::hexfloat << v[3 * i + k]
                      << " -> " << p[i][k];
    for (int k = 0; k < 2; ++k)
      if (bits(uv[i][k]) != modelBits(bits(v[3 * i + 1 + k])) && ++wrong <= 5)
        ADD_FAILURE() << "dvec2 component " << k << " of " << i << ": " << std::hexfloat
                      << v[3 * i + 1 + k] << " -> " << uv[i][k];
  }
  EXPECT_EQ(wrong, 0u);
}

// Ties go to even, a tie below a power of two carries into the exponent,
// and 0.1 becomes 0x1.99999ap-4 (13421773 * 2^-27 = 0.100000001490116...).
TEST(FloatRounding, EdgeCases) {
  struct Case {
    double in, out;
  };
  volatile Case cases[] = {
      {0.1, 0x1.99999ap-4},
      {1.0 + 0x1p-24, 1.0},                 // tie, kept part even: down
      {1.0 + 0x3p-24, 1.0 + 0x1p-22},       // tie, kept part odd: up
      {1.0 + 0x1p-24 + 0x1p-52, 1.0 + 0x1p-23},  // just above the tie: up
      {0x1.ffffffp0, 2.0},                  // tie at the top of a binade: carry
      {-0.1, -0x1.99999ap-4},
      {0.0, 0.0},
  };
  for (const volatile Case& c : cases) {
    const double in = c.in, out = c.out;
    EXPECT_EQ(bits(roundedToFloat(in)), bits(out)) << std::hexfloat << in;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(nearestFloat(in)), std::bit_cast<std::uint32_t>(float(out)))
        << std::hexfloat << in;
  }
}
