#include "assets/gaussian_heightfield.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include <tbb/parallel_for.h>

#include "assets/format_number.hpp"
#include "assets/real_fft2d.hpp"
#include "assets/slope_statistics.hpp"
#include "assets/white_noise.hpp"
#include "common/error.hpp"

namespace facet::assets {

namespace {

// The quadratic form A of C(τ) = σ_h² exp(−τᵀAτ) (docs/assets.md, eq. A2).
struct AcfForm {
  double xx, yy, xy;
};

AcfForm acf_form(const GaussianHeightfieldParams& p) {
  double theta = p.angle_deg * std::numbers::pi / 180.0;
  double c = std::cos(theta), s = std::sin(theta);
  double kx = 1.0 / (p.corr_x * p.corr_x), ky = 1.0 / (p.corr_y * p.corr_y);
  return {c * c * kx + s * s * ky, s * s * kx + c * c * ky, c * s * (kx - ky)};
}

double quadratic(const AcfForm& a, double x, double y) { return a.xx * x * x + 2.0 * a.xy * x * y + a.yy * y * y; }

// Lag of grid offset i on a periodic axis of n texels, wrapped into [−n/2, n/2).
double wrapped_lag(int i, int n) { return i < (n + 1) / 2 ? i : i - n; }

// Periodised ACF on the grid: Σ over lattice images (|m|, |n| ≤ 2; farther ones are < e^−36 σ_h²).
// Rows in parallel; exponents past kExpUnderflow are skipped, as exp() returns exactly 0 there (and
// takes libm's slow underflow path to do so: most of a large field's images).
std::vector<double> periodised_acf(const GaussianHeightfieldParams& p) {
  constexpr double kExpUnderflow = 746.0;  // exp(-746) rounds to +0 in double
  AcfForm a = acf_form(p);
  double period_x = p.width * p.texel_size, period_y = p.height * p.texel_size;
  std::vector<double> acf(static_cast<std::size_t>(p.width) * p.height);
  tbb::parallel_for(0, p.height, [&](int j) {
    for (int i = 0; i < p.width; ++i) {
      double tau_x = wrapped_lag(i, p.width) * p.texel_size, tau_y = wrapped_lag(j, p.height) * p.texel_size;
      double sum = 0.0;
      for (int n = -2; n <= 2; ++n)
        for (int m = -2; m <= 2; ++m) {
          const double q = quadratic(a, tau_x + m * period_x, tau_y + n * period_y);
          if (!(q > kExpUnderflow)) sum += std::exp(-q);
        }
      acf[static_cast<std::size_t>(j) * p.width + i] = p.sigma_h * p.sigma_h * sum;
    }
  });
  return acf;
}

}  // namespace

void validate(const GaussianHeightfieldParams& p) {
  if (p.width < 2 || p.height < 2 || p.width > kMaxFieldSide || p.height > kMaxFieldSide)
    throw Error("heightfield size must be from 2x2 to " + std::to_string(kMaxFieldSide) + "x" +
                std::to_string(kMaxFieldSide) + ", got " + std::to_string(p.width) + "x" + std::to_string(p.height));
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(p.texel_size))
    throw Error("heightfield texel size must be positive, got " + format_number(p.texel_size));
  if (!std::isfinite(p.sigma_h) || p.sigma_h < 0.0)
    throw Error("heightfield sigma_h must be finite and >= 0, got " + format_number(p.sigma_h));
  if (!positive(p.corr_x) || !positive(p.corr_y))
    throw Error("heightfield correlation lengths must be positive, got " + format_number(p.corr_x) + ", " +
                format_number(p.corr_y));
  if (!std::isfinite(p.angle_deg)) throw Error("heightfield angle must be finite");
  AcfForm a = acf_form(p);
  double period_x = p.width * p.texel_size, period_y = p.height * p.texel_size;
  for (int n = -2; n <= 2; ++n)
    for (int m = -2; m <= 2; ++m)
      if ((m != 0 || n != 0) && quadratic(a, m * period_x, n * period_y) < 16.0)
        throw Error("heightfield correlation lengths too long for the " + format_number(period_x) + " x " +
                    format_number(period_y) +
                    " period: the ACF must decay to e^-16 at the periodic images "
                    "(about corr <= period/4 along each axis)");
}

double gaussian_acf(const GaussianHeightfieldParams& p, double tau_x, double tau_y) {
  return p.sigma_h * p.sigma_h * std::exp(-quadratic(acf_form(p), tau_x, tau_y));
}

SlopeCovariance analytic_slope_covariance(const GaussianHeightfieldParams& p) {
  AcfForm a = acf_form(p);
  double two_var = 2.0 * p.sigma_h * p.sigma_h;
  return {two_var * a.xx, two_var * a.yy, two_var * a.xy};  // eq. A3
}

ScalarField generate_gaussian_heightfield(const GaussianHeightfieldParams& p) {
  validate(p);
  std::size_t n = static_cast<std::size_t>(p.width) * p.height;
  RealFft2d fft(p.width, p.height);

  // Power spectrum of the grid process: the DFT of its (real, even) periodised ACF. It is real and
  // non-negative up to rounding (a sum of aliases of the continuous spectrum), clamped at 0.
  std::vector<std::complex<double>> filter = fft.forward(periodised_acf(p));
  for (auto& s : filter) s = std::sqrt(std::max(s.real(), 0.0));

  GaussianWhiteNoise noise(p.seed);
  std::vector<double> white(n);
  for (double& w : white) w = noise.next();
  std::vector<std::complex<double>> spectrum = fft.forward(white);
  for (std::size_t k = 0; k < spectrum.size(); ++k) spectrum[k] *= filter[k];
  // E|W_k|² = N, so with the 1/N of the inverse DFT E[h²] = (1/N) Σ_k S_k = C_per(0) (eq. A4).
  std::vector<double> heights = fft.inverse(std::move(spectrum));

  double mean = 0.0;
  for (double h : heights) mean += h;
  mean /= static_cast<double>(n);
  double variance = 0.0;
  for (double& h : heights) {
    h -= mean;
    variance += h * h;
  }
  variance /= static_cast<double>(n);
  double scale = variance > 0.0 ? p.sigma_h / std::sqrt(variance) : 0.0;
  for (double& h : heights) h *= scale;
  return {p.width, p.height, std::move(heights)};
}

ExrMetadata heightfield_metadata(const GaussianHeightfieldParams& p, const ScalarField& field) {
  SlopeCovariance analytic = analytic_slope_covariance(p);
  SampleSlopeStatistics sample = forward_difference_slopes(field, p.texel_size);
  return {
      {"facet:generator", std::string("gaussian_heightfield")},
      {"facet:seed", std::to_string(p.seed)},  // a string: EXR ints are 32-bit
      {"facet:sigma_h", p.sigma_h},
      {"facet:corr_x", p.corr_x},
      {"facet:corr_y", p.corr_y},
      {"facet:angle_deg", p.angle_deg},
      {"facet:texel_size", p.texel_size},
      {"facet:slope_var_x", analytic.var_x},
      {"facet:slope_var_y", analytic.var_y},
      {"facet:slope_cov_xy", analytic.cov_xy},
      {"facet:sample_slope_var_x", sample.var_x},
      {"facet:sample_slope_var_y", sample.var_y},
      {"facet:sample_slope_cov_xy", sample.cov_xy},
  };
}

}  // namespace facet::assets
