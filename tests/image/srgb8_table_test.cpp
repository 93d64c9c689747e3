// The table-driven 8-bit sRGB encoding against the formula it replaces, srgb_display8: at and around
// every step, over 200 000 log-uniform values, and at the values the formula treats specially.
#include "image/srgb8_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "image/srgb.hpp"

namespace facet {
namespace {

TEST(Srgb8Table, EqualsTheFormulaAroundEveryStep) {
  const Srgb8Table& table = srgb8_table();
  int steps_seen = 0;
  // Walk up from each code's first value: the code must change exactly there.
  for (int code = 1; code <= 255; ++code) {
    // The value half-way between the codes, where the formula's code turns from code-1 to code.
    const double near = srgb_decode((code - 0.5) / 255.0);
    double x = near;
    for (int i = 0; i < 64 && srgb_display8(x) >= code; ++i) x = std::nextafter(x, 0.0);
    for (int i = 0; i < 128; ++i, x = std::nextafter(x, 2.0)) {
      ASSERT_EQ(table(x), srgb_display8(x)) << "x = " << x << " near code " << code;
      if (i > 0 && srgb_display8(x) != srgb_display8(std::nextafter(x, 0.0))) ++steps_seen;
    }
  }
  // Each walk crossed its step (so the comparison above was made on both sides of every step).
  EXPECT_EQ(steps_seen, 255);
}

TEST(Srgb8Table, EqualsTheFormulaOnLogUniformValues) {
  const Srgb8Table& table = srgb8_table();
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> log10(-12.0, 1.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = std::pow(10.0, log10(rng));
    ASSERT_EQ(table(x), srgb_display8(x)) << "x = " << x;
  }
}

TEST(Srgb8Table, SpecialValues) {
  const Srgb8Table& table = srgb8_table();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (double x : {0.0, -0.0, -1.0, -kInf, std::numeric_limits<double>::quiet_NaN(),
                   std::numeric_limits<double>::denorm_min(), std::numeric_limits<double>::min(), 1.0,
                   std::nextafter(1.0, 0.0), 7.0, kInf})
    EXPECT_EQ(table(x), srgb_display8(x)) << "x = " << x;
}

}  // namespace
}  // namespace facet
