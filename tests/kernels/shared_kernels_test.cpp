// Both C++ twins of the shared GLSL kernels compile, and round their constants to their own precision.
#include <gtest/gtest.h>

#include "kernels/shared.hpp"

double second_tu_pi();

namespace {

TEST(SharedKernels, ConstantsRoundedPerPrecision) {
  using namespace facet::kernels;
  static_assert(std::is_same_v<f32::real, float>);
  static_assert(std::is_same_v<f64::real, double>);
  EXPECT_EQ(static_cast<float>(3.14159265358979323846), [] {
    using namespace f32;
    return FACET_PI;
  }());
  EXPECT_EQ(3.14159265358979323846, [] {
    using namespace f64;
    return FACET_PI;
  }());
  EXPECT_EQ(second_tu_pi(), 3.14159265358979323846);
}

}  // namespace
