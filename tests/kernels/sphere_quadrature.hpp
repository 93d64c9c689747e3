// Brute-force reference for the cross-section tests: sigma(u) = int D(m) max(0, m.w) dm integrated
// over the polar angle of m, with the azimuthal integral of the clamped cosine done in closed form
// (the Dirac-ring cross-section, d'Eon eq. 8 divided by 2 pi), by adaptive Gauss-Kronrod. This uses
// neither the closed forms nor the variable t = m.w of the exact spherical-Gaussian code.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>

namespace facet::test {

// int_0^{2 pi} max(0, a + b cos phi) dphi, b >= 0.
inline double ring_clamped_cosine(double a, double b) {
  if (b <= std::abs(a)) return a > 0.0 ? 2.0 * std::numbers::pi * a : 0.0;
  return 2.0 * (a * std::acos(-a / b) + std::sqrt(b * b - a * a));
}

// D_of_theta: per-steradian density as a function of the polar angle theta_m (azimuthally symmetric).
// width: angular scale of D near theta_m = 0; horizon_width (0: none): the scale of the mass of D
// just above theta_m = pi/2 (1/alpha for very rough Beckmann and GGX). Both place breakpoints.
inline double sigma_by_quadrature(const std::function<double(double)>& D_of_theta, double u, double width,
                                  double horizon_width = 0.0) {
  double theta_u = std::acos(std::clamp(u, -1.0, 1.0));
  double s_u = std::sqrt(std::max(0.0, (1.0 - u) * (1.0 + u)));
  auto integrand = [&](double th) {
    return D_of_theta(th) * std::sin(th) * ring_clamped_cosine(std::cos(th) * u, std::sin(th) * s_u);
  };
  std::vector<double> breaks = {0.0, std::numbers::pi / 2, std::numbers::pi};  // GGX jumps to 0 at pi/2
  double kink = std::abs(std::numbers::pi / 2 - theta_u);
  for (double b : {kink, std::numbers::pi - kink}) breaks.push_back(b);
  for (double k : {1.0, 3.0, 10.0, 30.0, 100.0, 300.0}) breaks.push_back(k * width);
  if (horizon_width > 0.0)
    for (double k : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0}) breaks.push_back(std::numbers::pi / 2 - k * horizon_width);
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    double a = std::max(breaks[i], 0.0);
    double b = std::min(breaks[i + 1], std::numbers::pi);
    if (!(b > a)) continue;
    sum += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(integrand, a, b, 12, 1e-13);
  }
  return sum;
}

}  // namespace facet::test
