// Pixel-wise metrics against values worked out by hand on tiny images.
#include "image/metrics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "common/error.hpp"

namespace facet {
namespace {

Image random_image(int width, int height, unsigned seed, float lo = 0.0f, float hi = 2.0f) {
  Image image(width, height);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> value(lo, hi);
  for (float& v : image.rgb) v = value(rng);
  return image;
}

TEST(Metrics, IdenticalImagesHaveNoError) {
  const Image a = random_image(8, 5, 1);
  EXPECT_EQ(rmse(a, a), 0.0);
  EXPECT_EQ(relative_mse(a, a), 0.0);
  EXPECT_EQ(max_abs_error(a, a), 0.0);
  EXPECT_EQ(psnr(a, a), std::numeric_limits<double>::infinity());
  for (float v : absolute_error_map(a, a).values) EXPECT_EQ(v, 0.0f);
}

TEST(Metrics, ConstantOffset) {
  // b = a + 0.1 everywhere: RMSE = max = 0.1 and PSNR (peak 1) = 10 log10(1/0.01) = 20 dB.
  const Image reference(4, 3, glm::vec3(0.25f));
  const Image test(4, 3, glm::vec3(0.25f + 0.125f));  // exact in float: the error is exactly 1/8
  EXPECT_DOUBLE_EQ(rmse(test, reference), 0.125);
  EXPECT_DOUBLE_EQ(max_abs_error(test, reference), 0.125);
  EXPECT_NEAR(psnr(test, reference), 20.0 * std::log10(8.0), 1e-12);  // 18.0618 dB
  EXPECT_NEAR(psnr(test, reference, 4.0), 20.0 * std::log10(32.0), 1e-12);
  // relMSE: (1/8)^2 / ((1/4)^2 + 0.01) = 0.015625 / 0.0725.
  EXPECT_NEAR(relative_mse(test, reference), 0.015625 / 0.0725, 1e-15);
}

TEST(Metrics, HandComputedTwoPixels) {
  // Test (1,0,0),(0,0,0.5) against reference (0,0,0),(0,0,1): the squared errors are 1, 0, 0, 0, 0, 0.25.
  Image test(2, 1), reference(2, 1);
  test.set(0, 0, {1.0f, 0.0f, 0.0f});
  test.set(1, 0, {0.0f, 0.0f, 0.5f});
  reference.set(1, 0, {0.0f, 0.0f, 1.0f});
  EXPECT_DOUBLE_EQ(rmse(test, reference), std::sqrt(1.25 / 6.0));
  EXPECT_DOUBLE_EQ(max_abs_error(test, reference), 1.0);
  EXPECT_NEAR(psnr(test, reference), 10.0 * std::log10(6.0 / 1.25), 1e-12);
  // relMSE: (1/(0 + 0.01) + 0.25/(1 + 0.01)) / 6; the dark reference pixel dominates, as designed.
  EXPECT_NEAR(relative_mse(test, reference), (100.0 + 0.25 / 1.01) / 6.0, 1e-12);
  // Swapping roles changes only relMSE (its denominator is the reference).
  EXPECT_NEAR(relative_mse(reference, test), (1.0 / 1.01 + 0.25 / 0.26) / 6.0, 1e-12);
  const ScalarImage abs_map = absolute_error_map(test, reference);
  EXPECT_FLOAT_EQ(abs_map.values[0], 1.0f / 3.0f);
  EXPECT_FLOAT_EQ(abs_map.values[1], 0.5f / 3.0f);
  const ScalarImage rel_map = relative_error_map(test, reference);
  EXPECT_FLOAT_EQ(rel_map.values[0], static_cast<float>(100.0 / 3.0));
  EXPECT_FLOAT_EQ(rel_map.values[1], static_cast<float>(0.25 / 1.01 / 3.0));
}

TEST(Metrics, SymmetricWhereTheyShouldBe) {
  const Image a = random_image(16, 9, 2), b = random_image(16, 9, 3);
  EXPECT_DOUBLE_EQ(rmse(a, b), rmse(b, a));
  EXPECT_DOUBLE_EQ(psnr(a, b), psnr(b, a));
  EXPECT_DOUBLE_EQ(max_abs_error(a, b), max_abs_error(b, a));
  EXPECT_GT(rmse(a, b), 0.0);
}

TEST(Metrics, ExtremeButFiniteValuesStayFinite) {
  // Float max squared overflows float but not the double accumulator.
  const float big = std::numeric_limits<float>::max();
  const Image a(2, 2, glm::vec3(big)), b(2, 2, glm::vec3(-big));
  EXPECT_DOUBLE_EQ(rmse(a, b), 2.0 * big);
  EXPECT_TRUE(std::isfinite(relative_mse(a, b)));
  EXPECT_TRUE(std::isfinite(psnr(a, b)));
  const Image tiny(2, 2, glm::vec3(std::numeric_limits<float>::denorm_min())), zero(2, 2);
  EXPECT_GT(psnr(tiny, zero), 800.0);
  EXPECT_TRUE(std::isfinite(psnr(tiny, zero)));
}

TEST(Metrics, RejectsMismatchedEmptyAndNonFinite) {
  const Image a(4, 4), b(4, 5), empty;
  EXPECT_THROW(rmse(a, b), Error);
  EXPECT_THROW(relative_mse(b, a), Error);
  EXPECT_THROW(psnr(a, b), Error);
  EXPECT_THROW(max_abs_error(a, b), Error);
  EXPECT_THROW(absolute_error_map(a, b), Error);
  EXPECT_THROW(rmse(empty, empty), Error);
  Image nan = a;
  nan.rgb[5] = std::numeric_limits<float>::quiet_NaN();
  try {
    rmse(a, nan);
    FAIL() << "NaN accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("reference image has 1 non-finite"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace facet
