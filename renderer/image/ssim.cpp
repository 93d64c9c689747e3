#include "image/ssim.hpp"

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "image/metrics.hpp"
#include "image/srgb.hpp"

namespace facet {
namespace {

constexpr int kRadius = kSsimWindow / 2;
constexpr double kSigma = 1.5;
constexpr double kC1 = 0.01 * 0.01;  // (K1 L)^2, L = 1
constexpr double kC2 = 0.03 * 0.03;  // (K2 L)^2

// The 2D window is the outer product of this normalised 1D Gaussian, so it sums to 1 as well.
std::array<double, kSsimWindow> gaussian_weights() {
  std::array<double, kSsimWindow> w{};
  double sum = 0.0;
  for (int i = 0; i < kSsimWindow; ++i)
    sum += w[i] = std::exp(-double((i - kRadius) * (i - kRadius)) / (2 * kSigma * kSigma));
  for (double& v : w) v /= sum;
  return w;
}

// Gaussian-weighted mean of `plane` over every valid window, separably: rows, then columns.
std::vector<double> window_means(const std::vector<double>& plane, int width, int height) {
  static const std::array<double, kSsimWindow> w = gaussian_weights();
  const int out_w = width - 2 * kRadius, out_h = height - 2 * kRadius;
  std::vector<double> rows(static_cast<std::size_t>(out_w) * height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < out_w; ++x) {
      double sum = 0.0;
      for (int k = 0; k < kSsimWindow; ++k) sum += w[k] * plane[static_cast<std::size_t>(y) * width + x + k];
      rows[static_cast<std::size_t>(y) * out_w + x] = sum;
    }
  std::vector<double> means(static_cast<std::size_t>(out_w) * out_h);
  for (int y = 0; y < out_h; ++y)
    for (int x = 0; x < out_w; ++x) {
      double sum = 0.0;
      for (int k = 0; k < kSsimWindow; ++k) sum += w[k] * rows[static_cast<std::size_t>(y + k) * out_w + x];
      means[static_cast<std::size_t>(y) * out_w + x] = sum;
    }
  return means;
}

}  // namespace

ScalarImage display_luma(const Image& image) {
  ScalarImage luma(image.width, image.height);
  for (std::size_t p = 0; p < luma.pixel_count(); ++p) {
    const glm::vec3 c = image.at(p);
    luma.values[p] =
        static_cast<float>(0.2126 * srgb_display(c.r) + 0.7152 * srgb_display(c.g) + 0.0722 * srgb_display(c.b));
  }
  return luma;
}

ScalarImage ssim_map(const ScalarImage& x, const ScalarImage& y) {
  if (x.width != y.width || x.height != y.height)
    throw Error("cannot compare images of different sizes: " + std::to_string(x.width) + "x" +
                std::to_string(x.height) + " vs " + std::to_string(y.width) + "x" + std::to_string(y.height));
  if (x.width < kSsimWindow || x.height < kSsimWindow)
    throw Error("SSIM needs images of at least 11x11 pixels, got " + std::to_string(x.width) + "x" +
                std::to_string(x.height));
  // Moments in double: σ² = E[x²] - μ² cancels when the window is nearly flat.
  const std::size_t n = x.pixel_count();
  std::vector<double> xs(n), ys(n), xx(n), yy(n), xy(n);
  for (std::size_t i = 0; i < n; ++i) {
    xs[i] = x.values[i];
    ys[i] = y.values[i];
    xx[i] = xs[i] * xs[i];
    yy[i] = ys[i] * ys[i];
    xy[i] = xs[i] * ys[i];
  }
  const auto mu_x = window_means(xs, x.width, x.height), mu_y = window_means(ys, x.width, x.height);
  const auto e_xx = window_means(xx, x.width, x.height), e_yy = window_means(yy, x.width, x.height);
  const auto e_xy = window_means(xy, x.width, x.height);
  ScalarImage map(x.width - 2 * kRadius, x.height - 2 * kRadius);
  for (std::size_t i = 0; i < map.pixel_count(); ++i) {
    const double sigma_xx = e_xx[i] - mu_x[i] * mu_x[i], sigma_yy = e_yy[i] - mu_y[i] * mu_y[i];
    const double sigma_xy = e_xy[i] - mu_x[i] * mu_y[i];
    // Wang et al. 2004, eq. (13).
    map.values[i] = static_cast<float>((2 * mu_x[i] * mu_y[i] + kC1) * (2 * sigma_xy + kC2) /
                                       ((mu_x[i] * mu_x[i] + mu_y[i] * mu_y[i] + kC1) * (sigma_xx + sigma_yy + kC2)));
  }
  return map;
}

double ssim(const Image& test, const Image& reference) {
  check_comparable(test, reference);
  const ScalarImage map = ssim_map(display_luma(test), display_luma(reference));
  double sum = 0.0;
  for (float v : map.values) sum += v;
  return sum / static_cast<double>(map.pixel_count());
}

}  // namespace facet
