#include "kernels/cross_section_exact.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/bessel.hpp>

#include "kernels/shared.hpp"

namespace facet::kernels {
namespace {

// e^-x I_0(x) for x >= 0: Boost's I_0 below 500 (no overflow there), the asymptotic series
// sum_k ((2k-1)!!)^2 / (k! (8x)^k) / sqrt(2 pi x) above, whose 8th term is < 1e-19 at x = 500.
double bessel_i0_scaled(double x) {
  if (x < 500.0) return std::exp(-x) * boost::math::cyl_bessel_i(0, x);
  double inv_8x = 1.0 / (8.0 * x);
  double term = 1.0;
  double sum = 1.0;
  for (int k = 1; k < 8; ++k) {
    term *= (2.0 * k - 1.0) * (2.0 * k - 1.0) * inv_8x / k;
    sum += term;
  }
  return sum / std::sqrt(2.0 * std::numbers::pi * x);
}

}  // namespace

// With t = m.w = cos(beta) and psi the azimuth of m around w, m_z = t u + sin(beta) s_u cos(psi);
// the psi integral of exp(kappa m_z) is 2 pi exp(kappa t u) I_0(kappa sin(beta) s_u), so
//   sigma = kappa/(1 - exp(-2 kappa)) int_0^{pi/2} cos(b) sin(b) exp(-2 kappa sin^2((b - theta_u)/2))
//           e^-x I_0(x) db,  x = kappa sin(b) s_u,  theta_u = acos u,
// where every factor is <= 1 (no overflow for any kappa). The integrand is a bump of width
// 1/sqrt(kappa) at b = theta_u: [0, pi/2] is split there and at theta_u +- {1, 2.5, 5, 10, 20, 40}
// widths, and each piece gets a 30-point Gauss-Legendre rule.
double sg_cross_section_exact(double alpha, double u) {
  u = std::clamp(u, -1.0, 1.0);
  double kappa = 2.0 / (alpha * alpha);
  double s_u = std::sqrt((1.0 - u) * (1.0 + u));  // exact 1 - u (Sterbenz): consistent with acos(u)
  double theta_u = std::acos(u);
  double width = 1.0 / std::sqrt(kappa);
  auto integrand = [&](double b) {
    double half = std::sin(0.5 * (b - theta_u));
    return std::cos(b) * std::sin(b) * std::exp(-2.0 * kappa * half * half) *
           bessel_i0_scaled(kappa * std::sin(b) * s_u);
  };
  std::vector<double> breaks = {0.0, std::numbers::pi / 2};
  for (double k : {-40.0, -20.0, -10.0, -5.0, -2.5, -1.0, 0.0, 1.0, 2.5, 5.0, 10.0, 20.0, 40.0}) {
    double b = theta_u + k * width;
    if (b > 0.0 && b < std::numbers::pi / 2) breaks.push_back(b);
  }
  std::sort(breaks.begin(), breaks.end());
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    sum += boost::math::quadrature::gauss<double, 30>::integrate(integrand, breaks[i], breaks[i + 1]);
  return kappa / -std::expm1(-2.0 * kappa) * sum;
}

double cross_section(int ndf, double param, double u, bool exact) {
  if (!exact) return static_cast<double>(f32::ndf_sigma_u(ndf, static_cast<float>(u), static_cast<float>(param)));
  if (ndf == NDF_SG) return sg_cross_section_exact(param, u);
  return f64::ndf_sigma_u(ndf, u, param);
}

}  // namespace facet::kernels
