// Test cases and error measures of the visible slope kernel, shared by the quadrature test
// (visible_slope_test.cpp) and the GPU test (visible_slope_gpu_test.cpp).
//
// Error measures (brief): N relative (as |delta log N|), mean by sqrt(tr Sigma_s), covariance by
// tr Sigma_s, Sigma_s the true covariance of D_s. Targets: 1e-9 (double), 2e-4 (float), plus the
// *input floor*: inputs are themselves rounded to eps, and a relative change eps of theta or of the
// mean slope moves t by dt = eps ((cos theta + |s_o| sin theta)(1 + theta)/(sin theta sigma_o) + 2|t|),
// hence log N by (1 + |t|) dt, the mean by eps (|cot theta| + |s| + 2|mean of D_s|) and the covariance by 2 dt/(1 +
// |t|) (relative), which no implementation in that precision can beat (e.g. N = exp(-5e7) at t = -1e4).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "reference_visible_slope.hpp"

namespace facet::test {

inline constexpr double kPi = std::numbers::pi;

inline std::vector<SlopeCase> quadrature_cases() {
  std::vector<SlopeCase> cases = {
      // Heitz et al. 2013, Filtering Color Mapped Textures and Surfaces (supplemental), Table 3, rows 2-5 (row 1 is
      // theta = 0, tested exactly below).
      {1, 0, 1, 1, 0, 1.56, 0},
      {1, 1, 1, 1, 0.5, 1.56, kPi / 2},
      {1, 1, 1, 1, 0.75, 1.56, -kPi / 2},
      {1, 0, 1, 5, 0, 1.56, -kPi / 2},
      // Beyond the horizon: t = -2.4, -9.4, -99, -1e4.
      {3, 0, 1, 1, 0, 1.0, 0},
      {10, 0, 1, 1, 0, 1.0, 0.1},
      {100, 0, 1, 1, 0, 1.0, 0},
      {1e4, 0, 1, 1, 0, kPi / 4, 0},
      {1e4 * std::sqrt(2.0), 0, 2, 2, 1.9, kPi / 4, 0.3},
      // Tiny and huge variances, correlations +-(1 - 1e-6), near-grazing and near-normal views.
      {0, 0, 1e-10, 1e-10, 0, 0.5, 0.2},
      {0.5, 0, 1e-10, 1e-10, 0.99e-10, 1.1, 0.2},
      {2e-5, 1e-5, 1e-10, 3e-10, 1e-10, 1.5, 1.0},
      {0.5, 0.1, 1e4, 1e4, (1 - 1e-6) * 1e4, 1.2, 0.7},
      {0.5, 0.1, 1, 1, -(1 - 1e-6), 1.2, 0.7},
      {0.5, 0.1, 1, 1, 0, kPi / 2 - 1e-7, 0.7},
      {0.5, 0.1, 1, 2, 0.3, 1e-6, 0.7},
      {1.3, 0.1, 0.01, 1, 0.05, 0.66, 0.1},
  };
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int i = 0; i < 12; ++i) {
    const double var_x = std::pow(10.0, -2 + 3 * uni(rng)), var_y = std::pow(10.0, -2 + 3 * uni(rng));
    const double rho = 1.8 * uni(rng) - 0.9;
    cases.push_back({2 * uni(rng) - 1, 2 * uni(rng) - 1, var_x, var_y, rho * std::sqrt(var_x * var_y), 1.55 * uni(rng),
                     2 * kPi * uni(rng)});
  }
  return cases;
}

struct Errors {
  double log_N, mean, cov;
};

template <class Result>
Errors errors(const SlopeMoments& r, const Result& k) {
  const double tr = r.var_x + r.var_y;
  return {std::abs(static_cast<double>(k.log_N) - r.log_N),
          std::max(std::abs(k.mean.x - r.mean_x), std::abs(k.mean.y - r.mean_y)) / std::sqrt(tr),
          std::max({std::abs(k.cov.x - r.var_x), std::abs(k.cov.y - r.var_y), std::abs(k.cov.z - r.c_xy)}) / tr};
}

// The input floor of the header comment, for precision eps.
inline Errors input_floor(const SlopeCase& k, const SlopeMoments& r, double eps) {
  // At theta = 0, D_s = p_s exactly and t is infinite: only the output's own rounding remains.
  if (k.theta == 0) return {0, 2 * eps * std::hypot(r.mean_x, r.mean_y) / std::sqrt(r.var_x + r.var_y), 2 * eps};
  const double c = std::cos(k.phi), s = std::sin(k.phi);
  const double mean_o = k.mean_x * c + k.mean_y * s;
  const double sigma_o = std::sqrt(k.var_x * c * c + k.var_y * s * s + 2 * k.c_xy * c * s);
  const double a = std::sin(k.theta) * sigma_o;
  const double t = (std::cos(k.theta) - mean_o * std::sin(k.theta)) / a;
  const double dt = eps * ((std::abs(std::cos(k.theta)) + std::abs(mean_o) * std::sin(k.theta)) * (1 + k.theta) / a +
                           2 * std::abs(t));  // |cos|: views below the horizon (cross-sections) too
  // The mean is a sum of terms of size |cot theta|, |s| and, through the regression of s_perp on
  // s_o, |mean of D_s| itself (which can exceed the others by orders of magnitude for strongly
  // correlated, thin laws beyond the horizon); a float result cannot be nearer than eps times that.
  const double size = std::abs(std::cos(k.theta) / std::sin(k.theta)) + std::hypot(k.mean_x, k.mean_y) +
                      2 * std::hypot(r.mean_x, r.mean_y);
  return {(1 + std::abs(t)) * dt, eps * size / std::sqrt(r.var_x + r.var_y), 2 * dt / (1 + std::abs(t))};
}

inline SlopeCase rounded_to_float(const SlopeCase& k) {
  auto f = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  return {f(k.mean_x), f(k.mean_y), f(k.var_x), f(k.var_y), f(k.c_xy), f(k.theta), f(k.phi)};
}

}  // namespace facet::test
