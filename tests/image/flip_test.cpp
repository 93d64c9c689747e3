// LDR-FLIP on constant images, where filtering changes nothing and features vanish, so the value
// follows from published CIELAB coordinates by hand; plus its invariants on textured images.
#include "image/flip.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/error.hpp"
#include "image/test_images.hpp"

namespace facet {
namespace {

// Hunt-adjusted CIELAB (a' = 0.01·L·a, b' = 0.01·L·b) of the sRGB primaries green and blue under
// D65, from the published CIELAB values (Lindbloom's tables; 4-5 significant digits).
double hunt_hyab_green_blue() {
  const double green[3] = {87.7347, -86.1827, 83.1793}, blue[3] = {32.3026, 79.1967, -107.8637};
  const double da = 0.01 * (green[0] * green[1] - blue[0] * blue[1]);
  const double db = 0.01 * (green[0] * green[2] - blue[0] * blue[2]);
  return std::abs(green[0] - blue[0]) + std::hypot(da, db);
}

// The paper's error redistribution with q_c = 0.7, p_c = 0.4, p_t = 0.95.
double redistributed(double hyab) {
  const double c_max = std::pow(hunt_hyab_green_blue(), 0.7), e = std::pow(hyab, 0.7);
  return e < 0.4 * c_max ? 0.95 / (0.4 * c_max) * e : 0.95 + (e - 0.4 * c_max) / (0.6 * c_max) * 0.05;
}

double cie_lightness(double y) { return y > 216.0 / 24389.0 ? 116.0 * std::cbrt(y) - 16.0 : 24389.0 / 27.0 * y; }

TEST(Flip, IdenticalImagesGiveZero) {
  Image image(20, 17);
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> value(0.0f, 1.5f);
  for (float& v : image.rgb) v = value(rng);
  for (float v : flip_map(image, image).values) EXPECT_EQ(v, 0.0f);
}

TEST(Flip, GreenAgainstBlueIsTheMaximum) {
  EXPECT_NEAR(flip(Image(16, 16, {0, 1, 0}), Image(16, 16, {0, 0, 1})), 1.0, 1e-6);
}

TEST(Flip, ConstantGreysMatchHandComputation) {
  // Greys have a = b = 0, so HyAB is |ΔL*|. Black/white (ΔL* = 100) falls in the upper branch:
  // 100^0.7 = 25.1 > 0.4·c_max = 16.5, giving 0.967; 0.20 vs 0.21 (ΔL* = 1.10) in the lower one.
  // Tolerance: the published Lab values carry 5-6 digits, moving c_max by ~1e-5 relative (seen: 1e-6).
  EXPECT_NEAR(flip(Image(12, 12, glm::vec3(1.0f)), Image(12, 12, glm::vec3(0.0f))), redistributed(100.0), 1e-5);
  EXPECT_NEAR(redistributed(100.0), 0.9674, 1e-3);
  const double dl = cie_lightness(0.21) - cie_lightness(0.20);
  EXPECT_NEAR(flip(Image(12, 12, glm::vec3(0.21f)), Image(12, 12, glm::vec3(0.20f))), redistributed(dl), 1e-5);
  // Values beyond the display range are clamped first: 5 looks like 1, -2 like 0.
  EXPECT_NEAR(flip(Image(12, 12, glm::vec3(5.0f)), Image(12, 12, glm::vec3(-2.0f))), redistributed(100.0), 1e-5);
}

using test::noisy;

TEST(Flip, SymmetricBoundedAndMonotoneInNoise) {
  Image base(40, 30);
  for (int y = 0; y < base.height; ++y)
    for (int x = 0; x < base.width; ++x) base.set(x, y, glm::vec3(0.02f * x, 0.4f + 0.3f * std::sin(0.4f * y), 0.3f));
  const Image weak = noisy(base, 0.03f, 1), strong = noisy(base, 0.3f, 2);
  const ScalarImage ab = flip_map(weak, strong), ba = flip_map(strong, weak);
  EXPECT_EQ(ab.values, ba.values);
  for (float v : ab.values) {
    EXPECT_GE(v, 0.0f);
    EXPECT_LE(v, 1.0f);
  }
  EXPECT_LT(flip(weak, base), flip(strong, base));
  EXPECT_GT(flip(weak, base), 0.0);
}

TEST(Flip, FineDetailMattersMoreWhenViewedCloser) {
  // A one-pixel checkerboard against its mean grey: at fewer pixels per degree the pattern is
  // coarser on the retina, less is filtered away, and the difference is larger.
  Image checker(32, 32), grey(32, 32, glm::vec3(0.5f));
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) checker.set(x, y, glm::vec3((x + y) % 2 ? 1.0f : 0.0f));
  const double far = flip(checker, grey, 67.0), near = flip(checker, grey, 10.0);
  EXPECT_LT(far, near);
  EXPECT_LT(far, flip(Image(32, 32, glm::vec3(1.0f)), Image(32, 32)));
}

TEST(Flip, RejectsMismatchedAndNonFinite) {
  EXPECT_THROW(flip(Image(4, 4), Image(4, 5)), Error);
  Image nan(4, 4);
  nan.rgb[0] = std::nanf("");
  EXPECT_THROW(flip(nan, Image(4, 4)), Error);
  EXPECT_NO_THROW(flip(Image(1, 1), Image(1, 1)));
}

}  // namespace
}  // namespace facet
