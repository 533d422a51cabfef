// The batch line's numbers (io/src/shortest_double.cpp): the same characters std::to_chars writes
// (docs/spec.md §2.8 promises its spelling), on doubles of every kind — random bit patterns,
// random values over the magnitudes a result holds, integers, powers of ten and of two with their
// neighbours (where the fixed and the scientific forms trade places), subnormals and the extremes.
// The buffer is exactly the 40 bytes the writer may use, so a sanitizer build sees any overrun.
#include "shortest_double.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>

namespace relpos::detail {
namespace {

std::string toChars(double v) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::string written(double v) {
  char buf[40];
  return std::string(buf, writeShortestDouble(buf, v));
}

// Checks v and counts a difference (the first few reported with both texts).
struct Comparison {
  long checked = 0, differ = 0;
  void check(double v) {
    ++checked;
    const std::string expected = toChars(v), got = written(v);
    if (expected == got) return;
    if (++differ <= 10) ADD_FAILURE() << "to_chars '" << expected << "', written '" << got << "'";
  }
};

TEST(ShortestDouble, SpellsEveryDoubleAsToChars) {
  Comparison c;
  std::mt19937_64 g(20261207);
  for (int i = 0; i < 400000; ++i) {
    const std::uint64_t bits = g();
    double v;
    std::memcpy(&v, &bits, sizeof v);
    if (std::isfinite(v)) c.check(v);
  }
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> decade(-25, 20);
  for (int i = 0; i < 200000; ++i) {
    c.check(unit(g));                                     // a quaternion's coordinate
    c.check(unit(g) * std::pow(10.0, decade(g)));         // lengths of any scale
    c.check(std::round(unit(g) * 1e6));                   // integers: fixed, with .0 added later
    c.check(std::round(unit(g) * 1e16));                  // up to and past 2^53
    c.check(std::round(unit(g) * 1e6) * 1e-3);            // millimetres in metres
    c.check(std::ldexp(std::round(unit(g) * 1e4), -20));  // short binary fractions
  }
  for (int e = -330; e <= 310; ++e) {
    const double p = std::pow(10.0, e);
    for (double v : {p, 5 * p, 1.5 * p, 123456789 * p}) {
      c.check(v), c.check(-v);
      c.check(std::nextafter(v, 0.0)), c.check(std::nextafter(v, HUGE_VAL));
    }
  }
  for (int e = -1074; e <= 1023; ++e) {
    const double p = std::ldexp(1.0, e);
    c.check(p), c.check(std::nextafter(p, 0.0)), c.check(std::nextafter(p, HUGE_VAL));
  }
  for (int i = -20000; i <= 20000; ++i) c.check(i), c.check(i / 8.0), c.check(i * 1e-7);
  for (double v : {0.0, -0.0, 9007199254740991.0, 9007199254740992.0, -9007199254740993.0,
                   std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(),
                   std::numeric_limits<double>::max(), std::numeric_limits<double>::lowest(),
                   std::numeric_limits<double>::epsilon(), 3.141592653589793, 1e-7, 1e5, 1e21, 1e22,
                   1e23, 123456789012345680000.0, 0.0001, 0.00001})
    c.check(v);
  EXPECT_EQ(c.differ, 0) << "of " << c.checked;
  EXPECT_GT(c.checked, 1500000);
}

TEST(ShortestDouble, WritesTheFormsTheSpecShows) {
  // docs/spec.md §2.8's examples, before the writer adds ".0" to integral ones.
  EXPECT_EQ(written(100.0), "100");
  EXPECT_EQ(written(1e-7), "1e-07");
  EXPECT_EQ(written(-0.0), "-0");
  EXPECT_EQ(written(100000.0), "1e+05");
  EXPECT_EQ(written(0.0001), "1e-04");  // shorter than 0.0001
  EXPECT_EQ(written(0.001), "0.001");   // as long as 1e-03: fixed
  EXPECT_EQ(written(0.0550878194046821), "0.0550878194046821");
  EXPECT_EQ(written(-2.2250738585072014e-308), "-2.2250738585072014e-308");
}

}  // namespace
}  // namespace relpos::detail
