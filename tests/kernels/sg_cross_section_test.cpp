// The spherical-Gaussian cross-section: the exact CPU quadrature against three independent
// references, the fast GPU kernel against the exact one over the whole domain, and the accuracy
// claims of the paper's approximations (d'Eon eqs. 22, 40, 44, 38 truncated) measured.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/special_functions/bessel.hpp>
#include <boost/math/special_functions/legendre.hpp>

#include "kernels/cross_section_exact.hpp"
#include "kernels/shared.hpp"
#include "sphere_quadrature.hpp"

namespace sg_cross_section_test {

using namespace facet::kernels;
constexpr double kPi = std::numbers::pi;

std::vector<double> log_grid(double lo, double hi, int n) {
  std::vector<double> g;
  for (int i = 0; i <= n; ++i) g.push_back(lo * std::pow(hi / lo, double(i) / n));
  return g;
}
std::vector<double> u_grid(int n) {
  std::vector<double> g;
  for (int i = 0; i <= n; ++i) g.push_back(-1.0 + 2.0 * i / n);
  for (double u : {-1e-3, 1e-3, -1e-6, 1e-6, 0.999999, -0.999999}) g.push_back(u);
  return g;
}

// e^-x I_nu(x) via Boost below 500 and the Hankel asymptotic series above (8 terms, < 1e-17 there).
double bessel_scaled(double nu, double x) {
  if (x < 500.0) return std::exp(-x) * boost::math::cyl_bessel_i(nu, x);
  double mu = 4.0 * nu * nu, term = 1.0, sum = 1.0;
  for (int k = 1; k < 9; ++k) {
    term *= -(mu - (2.0 * k - 1.0) * (2.0 * k - 1.0)) / (k * 8.0 * x);
    sum += term;
  }
  return sum / std::sqrt(2.0 * kPi * x);
}

// Endpoint and midpoint formulas (docs/errata.md#cross-section-endpoints-swapped: eq. 30 is sigma(+1)), in forms stable
// for every kappa.
double sigma_plus_one(double kappa) {
  // [1 - (1 - e^-k)/k] / (1 - e^-2k); the bracket by its alternating series for small kappa.
  double bracket;
  if (kappa < 0.01) {
    bracket = 0.0;
    double term = 1.0;
    for (int n = 1; n < 12; ++n) {
      term *= -kappa / (n + 1);
      bracket -= term;
    }
  } else {
    bracket = 1.0 + std::expm1(-kappa) / kappa;
  }
  return bracket / -std::expm1(-2.0 * kappa);
}
double sigma_zero(double kappa) {  // eq. (31): I_1(k)/(2 sinh k)
  return bessel_scaled(1.0, kappa) / -std::expm1(-2.0 * kappa);
}
double langevin(double kappa) {  // E[m_z] (eq. 35): in long double (its cancellation ~1e-19/kappa), series below 1e-3
  if (kappa < 1e-3) return kappa / 3.0 - kappa * kappa * kappa / 45.0;
  long double k = kappa;
  return static_cast<double>(1.0L / std::tanh(k) - 1.0L / k);
}

double sg_D_of_theta(double alpha, double th) {
  double kappa = 2.0 / (alpha * alpha);
  return kappa * std::exp(kappa * (std::cos(th) - 1.0)) / (2.0 * kPi * -std::expm1(-2.0 * kappa));
}

// Legendre series sigma = sum (2l+1)/2 c_l h_l P_l(u), c_l = I_{l+1/2}(k)/I_{1/2}(k) from Boost, h_l by
// Gauss-Legendre quadrature (exact for these polynomials).
double sigma_legendre(double alpha, double u, int terms) {
  double kappa = 2.0 / (alpha * alpha);
  double sum = 0.0;
  for (int l = 0; l < terms; ++l) {
    if (l > 1 && l % 2 == 1) continue;
    double c = boost::math::cyl_bessel_i(l + 0.5, kappa) / boost::math::cyl_bessel_i(0.5, kappa);
    double h = boost::math::quadrature::gauss<double, 40>::integrate(
        [&](double x) { return x * boost::math::legendre_p(l, x); }, 0.0, 1.0);
    sum += 0.5 * (2 * l + 1) * c * h * boost::math::legendre_p(l, u);
  }
  return sum;
}

TEST(SgCrossSectionExact, Endpoints) {
  for (double a : log_grid(1e-3, 1e3, 24)) {
    double k = 2.0 / (a * a);
    EXPECT_NEAR(sg_cross_section_exact(a, 1.0), sigma_plus_one(k), 1e-13) << a;
    EXPECT_NEAR(sg_cross_section_exact(a, -1.0), sigma_plus_one(k) - langevin(k), 1e-13) << a;
    EXPECT_NEAR(sg_cross_section_exact(a, 0.0), sigma_zero(k), 1e-13) << a;
  }
}

TEST(SgCrossSectionExact, OddPartIsLinear) {
  for (double a : log_grid(1e-3, 1e3, 12)) {
    for (double u : u_grid(10)) {
      double odd = sg_cross_section_exact(a, u) - sg_cross_section_exact(a, -u);
      EXPECT_NEAR(odd, u * langevin(2.0 / (a * a)), 2e-13) << a << " " << u;
      EXPECT_NEAR(f64::ndf_sg_mean_z(a), langevin(2.0 / (a * a)), 2e-15) << a;
    }
  }
}

TEST(SgCrossSectionExact, MatchesSphereQuadrature) {
  double worst = 0.0;
  for (double a : {1e-3, 3e-3, 0.01, 0.05, 0.1, 0.3, 1.0, 3.0, 10.0, 1e3}) {
    for (double u : u_grid(10)) {
      double ref =
          facet::test::sigma_by_quadrature([&](double th) { return sg_D_of_theta(a, th); }, u, std::min(a, 0.5));
      double got = sg_cross_section_exact(a, u);
      EXPECT_NEAR(got, ref, 1e-12) << "alpha " << a << " u " << u;
      worst = std::max(worst, std::abs(got - ref));
    }
  }
  std::printf("worst |exact - sphere quadrature| = %.3g\n", worst);
}

TEST(SgCrossSectionExact, MatchesLegendreSeriesForLargeAlpha) {
  double worst = 0.0;
  for (double a : {0.5, 1.0, 2.0, 10.0, 1e3}) {
    for (double u : u_grid(20)) {
      double got = sg_cross_section_exact(a, u);
      double ref = sigma_legendre(a, u, 60);
      EXPECT_NEAR(got, ref, 1e-13) << "alpha " << a << " u " << u;
      worst = std::max(worst, std::abs(got - ref));
    }
  }
  std::printf("worst |exact - Legendre(60 terms)| = %.3g\n", worst);
}

// The fast kernel (float and double twins) against the exact sigma on a dense grid over the whole
// domain alpha in [1e-3, 1e3], u in [-1, 1]. Target 1e-4; the design error is ~2e-5 (Legendre
// truncation at degree 40 and the cumulant expansion, both at the switch alpha = 0.1).
TEST(SgCrossSectionFast, WorstErrorOverDomain) {
  double worst32 = 0.0, worst64 = 0.0, at_alpha = 0.0, at_u = 0.0;
  for (double a : log_grid(1e-3, 1e3, 120)) {
    for (double u : u_grid(200)) {
      double ref = sg_cross_section_exact(a, u);
      double e32 = std::abs(f32::ndf_sg_sigma_u(float(u), float(a)) -
                            sg_cross_section_exact(double(float(a)), double(float(u))));
      double e64 = std::abs(f64::ndf_sg_sigma_u(u, a) - ref);
      if (e32 > worst32) {
        worst32 = e32;
        at_alpha = a;
        at_u = u;
      }
      worst64 = std::max(worst64, e64);
    }
  }
  std::printf("fast sigma_SG: worst abs error float %.3g (alpha %.4g, u %.4g), double %.3g\n", worst32, at_alpha, at_u,
              worst64);
  EXPECT_LT(worst32, 1e-4);
  EXPECT_LT(worst64, 1e-4);
}

// ---- The paper's approximations, measured on the ranges where it states their accuracy. ----
double sigma_beckmann(double m, double u) {  // eq. (22)
  double s = std::sqrt(std::max(0.0, 1.0 - u * u));
  if (s == 0.0) return std::max(u, 0.0);
  return 0.5 * (u * (1.0 + std::erf(u / (m * s))) + m * s * std::exp(-u * u / (m * m * s * s)) / std::sqrt(kPi));
}
double sigma_eq40(double m, double u) {
  double x = 1.0 / (m * m);
  return 0.25 * (std::tanh(x) * (u - m * m * std::abs(u)) + (-m * m - 2.0) * u + u / std::tanh(x)) +
         sigma_beckmann(m, u);
}
double sigma_eq44(double m, double u) {
  double c = 1.0 / std::tanh(2.0 / (m * m));
  return -0.25 * u * (m * m - 2.0 * c) +
         5.0 / 128.0 * (3.0 * u * u - 1.0) * (3.0 * m * m * m * m - 6.0 * m * m * c + 4.0) + 0.25;
}
double worst_error(double (*approx)(double, double), double lo, double hi) {
  double worst = 0.0;
  for (double m : log_grid(lo, hi, 40))
    for (double u : u_grid(100)) worst = std::max(worst, std::abs(approx(m, u) - sg_cross_section_exact(m, u)));
  return worst;
}
double sigma_sh12(double m, double u) { return sigma_legendre(m, u, 12); }

TEST(SgCrossSectionPaperClaims, Measured) {
  // Claim: Beckmann (eq. 22) within 1e-3 for m < 0.044.
  double beckmann = worst_error(sigma_beckmann, 1e-3, 0.044);
  // Claim: eq. (40) within 1e-3 for m < 0.25.
  double eq40 = worst_error(sigma_eq40, 1e-3, 0.25);
  // Claim: eq. (44) within 1e-3 for m > 1 (measured on [1, 1e3]).
  double eq44 = worst_error(sigma_eq44, 1.0, 1e3);
  // "12-term SH" between the two regimes (no accuracy stated): measured on [0.25, 1].
  double sh12 = worst_error(sigma_sh12, 0.25, 1.0);
  std::printf(
      "paper claims: Beckmann m<0.044: %.3g; eq.40 m<0.25: %.3g; eq.44 m>1: %.3g; 12-term SH on [0.25,1]: %.3g\n",
      beckmann, eq40, eq44, sh12);
  EXPECT_LT(beckmann, 1e-3);
  EXPECT_LT(eq40, 1e-3);
  EXPECT_LT(eq44, 1.1e-3);  // the claim (1e-3) fails narrowly: 1.03e-3, at m = 1 (docs/cross_sections.md)
}

}  // namespace sg_cross_section_test
