// SSIM against closed forms: constant images, and checkerboards whose local moments follow from the
// window's alternating sum alone.
#include "image/ssim.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "common/error.hpp"
#include "image/test_images.hpp"

namespace facet {
namespace {

constexpr double kC1 = 1e-4, kC2 = 9e-4;  // (0.01)^2 and (0.03)^2, Wang et al. 2004 with L = 1

ScalarImage checkerboard(int width, int height, float even, float odd) {
  ScalarImage image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) image.at(x, y) = (x + y) % 2 == 0 ? even : odd;
  return image;
}

TEST(Ssim, ConstantImagesGiveTheLuminanceTerm) {
  // σ = 0 in every window, so SSIM = (2ab + C1)/(a² + b² + C1) exactly.
  const double a = 0.3f, b = 0.6f;
  const ScalarImage map = ssim_map(ScalarImage(13, 12, 0.3f), ScalarImage(13, 12, 0.6f));
  ASSERT_EQ(map.width, 3);
  ASSERT_EQ(map.height, 2);
  for (float v : map.values) EXPECT_NEAR(v, (2 * a * b + kC1) / (a * a + b * b + kC1), 1e-7);
}

// x = m + d(-1)^(i+j). With normalised 1D weights w_k (k = -5..5) and s = (Σ w_k (-1)^k)², a window
// centred on parity p = ±1 has mean m + p·d·s and variance d²(1 - s²); two such boards have
// covariance d·d'·(1 - s²). The test derives s from its own Gaussian.
double expected_checkerboard_ssim(double x_even, double x_odd, double y_even, double y_odd, int out_w, int out_h) {
  double alternating = 0.0, total = 0.0;
  for (int k = -5; k <= 5; ++k) {
    const double w = std::exp(-k * k / (2 * 1.5 * 1.5));
    total += w;
    alternating += (k % 2 == 0 ? w : -w);
  }
  const double s = (alternating / total) * (alternating / total);
  const double mx = (x_even + x_odd) / 2, dx = (x_even - x_odd) / 2;
  const double my = (y_even + y_odd) / 2, dy = (y_even - y_odd) / 2;
  double sum = 0.0;
  for (int oy = 0; oy < out_h; ++oy)
    for (int ox = 0; ox < out_w; ++ox) {
      const double p = (ox + oy) % 2 == 0 ? 1.0 : -1.0;  // window centre (ox+5, oy+5) has the same parity
      const double mu_x = mx + p * dx * s, mu_y = my + p * dy * s;
      const double var_x = dx * dx * (1 - s * s), var_y = dy * dy * (1 - s * s), cov = dx * dy * (1 - s * s);
      sum += (2 * mu_x * mu_y + kC1) * (2 * cov + kC2) / ((mu_x * mu_x + mu_y * mu_y + kC1) * (var_x + var_y + kC2));
    }
  return sum / (out_w * out_h);
}

double mean(const ScalarImage& image) {
  double sum = 0.0;
  for (float v : image.values) sum += v;
  return sum / static_cast<double>(image.pixel_count());
}

TEST(Ssim, CheckerboardsMatchClosedForm) {
  struct Case {
    float x_even, x_odd, y_even, y_odd;
  };
  // Correlated, anti-correlated (negative SSIM), scaled contrast, and one flat board.
  for (const Case& c : {Case{0.7f, 0.3f, 0.6f, 0.4f}, Case{0.7f, 0.3f, 0.4f, 0.6f}, Case{0.9f, 0.1f, 0.55f, 0.45f},
                        Case{0.7f, 0.3f, 0.5f, 0.5f}}) {
    const int width = 20, height = 15;
    const double measured =
        mean(ssim_map(checkerboard(width, height, c.x_even, c.x_odd), checkerboard(width, height, c.y_even, c.y_odd)));
    const double expected = expected_checkerboard_ssim(c.x_even, c.x_odd, c.y_even, c.y_odd, width - 10, height - 10);
    // Map entries are stored as float: a few float ulps of a value of order 1.
    EXPECT_NEAR(measured, expected, 1e-6) << c.x_even << " " << c.x_odd << " " << c.y_even << " " << c.y_odd;
  }
  EXPECT_LT(expected_checkerboard_ssim(0.7, 0.3, 0.4, 0.6, 10, 5),
            -0.5);  // the anti-correlated case is strongly negative
}

// One bright pixel on black against a flat grey a: in the window whose centre is offset (k, l) from
// the impulse, μx = w_k w_l, σx² = μx(1 - μx), σxy = 0, σy = 0. This pins down every weight of the
// window (a checkerboard cannot: its alternating weight sum is only ~1e-4).
TEST(Ssim, ImpulseRevealsTheGaussianWindow) {
  const int size = 21, impulse = 10;
  const double a = 0.25f;
  ScalarImage x(size, size, 0.0f);
  x.at(impulse, impulse) = 1.0f;
  const ScalarImage map = ssim_map(x, ScalarImage(size, size, 0.25f));
  std::vector<double> w(11);
  double total = 0.0;
  for (int k = -5; k <= 5; ++k) total += w[k + 5] = std::exp(-k * k / (2 * 1.5 * 1.5));
  for (double& v : w) v /= total;
  for (int oy = 0; oy < map.height; ++oy)
    for (int ox = 0; ox < map.width; ++ox) {
      const int k = impulse - (ox + 5), l = impulse - (oy + 5);
      const double mu_x = std::abs(k) <= 5 && std::abs(l) <= 5 ? w[k + 5] * w[l + 5] : 0.0;
      const double var_x = mu_x * (1 - mu_x);
      const double expected = (2 * mu_x * a + kC1) * kC2 / ((mu_x * mu_x + a * a + kC1) * (var_x + kC2));
      EXPECT_NEAR(map.at(ox, oy), expected, 2e-7 * std::abs(expected) + 1e-7) << ox << ", " << oy;
    }
}

using test::noisy;

TEST(Ssim, IdentitySymmetryAndMonotoneInNoise) {
  Image base(48, 32);
  for (int y = 0; y < base.height; ++y)
    for (int x = 0; x < base.width; ++x) base.set(x, y, glm::vec3(0.02f * x, 0.5f + 0.4f * std::sin(0.3f * y), 0.25f));
  EXPECT_NEAR(ssim(base, base), 1.0, 1e-7);
  const Image a = noisy(base, 0.05f, 1), b = noisy(base, 0.2f, 2);
  EXPECT_DOUBLE_EQ(ssim(a, b), ssim(b, a));
  const double weak = ssim(a, base), strong = ssim(b, base);
  EXPECT_LT(weak, 1.0);
  EXPECT_LT(strong, weak);
  EXPECT_GT(strong, -1.0);
}

TEST(Ssim, DisplayLumaClampsAndEncodes) {
  Image image(4, 1);
  image.set(0, 0, {1.0f, 0.0f, 0.0f});
  image.set(1, 0, {0.5f, 0.5f, 0.5f});
  image.set(2, 0, {-4.0f, 1e30f, 2.0f});
  image.set(3, 0, {0.0f, 0.0f, 1.0f});
  const ScalarImage luma = display_luma(image);
  EXPECT_FLOAT_EQ(luma.values[0], 0.2126f);
  EXPECT_FLOAT_EQ(luma.values[1], static_cast<float>(1.055 * std::pow(0.5, 1 / 2.4) - 0.055));
  EXPECT_FLOAT_EQ(luma.values[2], 0.7152f + 0.0722f);
  EXPECT_FLOAT_EQ(luma.values[3], 0.0722f);
}

TEST(Ssim, RejectsSmallAndMismatchedImages) {
  EXPECT_THROW(ssim_map(ScalarImage(10, 20), ScalarImage(10, 20)), Error);
  EXPECT_THROW(ssim_map(ScalarImage(20, 20), ScalarImage(20, 21)), Error);
  EXPECT_THROW(ssim(Image(11, 11), Image(11, 12)), Error);
  EXPECT_NO_THROW(ssim(Image(11, 11), Image(11, 11)));
  // All black against all black: the constants keep 0/0 away.
  EXPECT_NEAR(ssim(Image(11, 11), Image(11, 11)), 1.0, 1e-7);
}

}  // namespace
}  // namespace facet
