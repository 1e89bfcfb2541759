// pov::num, the text of every number in an exported scene.pov: it is, by
// definition, the first of "%.6g" .. "%.17g" that strtod reads back as the
// same double. The definition is written out here, the slow way, and num
// must give the same text for every kind of double.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "povray/sdl.h"

using namespace xval;

namespace {

std::string firstPrecisionThatRoundTrips(double v) {
  if (v == 0.0) return std::signbit(v) ? "-0" : "0";
  char buf[40];
  for (int prec = 6; prec <= 17; ++prec) {
    std::snprintf(buf, sizeof buf, "%.*g", prec, v);
    if (std::strtod(buf, nullptr) == v) break;
  }
  return buf;
}

double fromBits(uint64_t b) {
  double d;
  std::memcpy(&d, &b, sizeof d);
  return d;
}

}  // namespace

TEST(PovSdl, NumIsTheFirstPrecisionThatRoundTrips) {
  std::vector<double> values = {1.0, -1.0, 0.1, 1.0 / 3.0, 2.0 / 3.0, 1e-300, 1e300, DBL_MAX, -DBL_MAX, DBL_MIN,
                                DBL_TRUE_MIN, 5e-324, 123456.5, 1234567.0, 0.0001, 0.00001, 9.5367431640625e-07,
                                std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  // Every power of two and its neighbours: where the rounding interval is
  // lopsided and the nearest p-digit decimal may not be the shortest.
  for (int e = -1074; e <= 1023; ++e) {
    const double p = std::ldexp(1.0, e);
    values.insert(values.end(), {p, std::nextafter(p, 0.0), std::nextafter(p, INFINITY), -p});
  }
  // Floats widened to double (what a mesh's float attributes become).
  std::mt19937_64 rng(20261202);
  std::uniform_real_distribution<float> coordinate(-4.0f, 4.0f);
  for (int k = 0; k < 100000; ++k) values.push_back(double(coordinate(rng)));
  // Doubles of every exponent, and short decimals.
  for (int k = 0; k < 100000; ++k) {
    const double d = fromBits(rng());
    if (std::isfinite(d)) values.push_back(d);
    values.push_back(double(int64_t(rng() % 2000001) - 1000000) / 1000.0);
  }
  int mismatches = 0;
  for (double v : values) {
    const std::string want = firstPrecisionThatRoundTrips(v);
    const std::string got = pov::num(v);
    if (got != want && ++mismatches <= 10) ADD_FAILURE() << "num(" << want << ") gave " << got;
  }
  EXPECT_EQ(mismatches, 0) << "of " << values.size() << " values";
  EXPECT_EQ(pov::num(std::nan("")), firstPrecisionThatRoundTrips(std::nan("")));
}
