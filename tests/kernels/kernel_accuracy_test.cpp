// The double kernels against 50-digit quadrature of their definitions (support/multiprecision_reference.hpp)
// over the dense sweeps of kernel_accuracy_sweeps.hpp; docs/kernel_accuracy.md tabulates the same sweeps
// (bench/kernel_accuracy.cpp). Each test prints its worst errors beside the bounds it enforces.
#include <gtest/gtest.h>

#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/special_functions/erf.hpp>

#include "kernel_accuracy_sweeps.hpp"

namespace {

using namespace facet::test;
using accuracy::Row;

void expect_within_bounds(const std::vector<Row>& rows) {
  for (const Row& r : rows) {
    std::printf(
        "%s, %s: worst %.2g at %s; %.2g where well conditioned (%d points); worst error/bound %.2g (%d points)\n",
        r.kernel.c_str(), r.quantity.c_str(), r.worst, r.where.c_str(), r.worst_conditioned, r.conditioned, r.excess,
        r.points);
    EXPECT_GT(r.points, 0) << r.kernel << " " << r.quantity;
    EXPECT_LE(r.excess, 1.0) << r.kernel << " " << r.quantity << ": " << r.worst << " at " << r.where;
  }
}

// The references themselves: their fixed Gauss-Legendre rule against adaptive exp_sinh, the integral
// definitions of erf/erfc against Boost.Math's own 50-digit erf/erfc (series and continued fractions, an
// independent method), and the visible slope product rule against the independent double-precision nested
// quadrature of reference_visible_slope.hpp.
TEST(KernelAccuracy, ReferencesAgreeWithIndependentMethods) {
  boost::math::quadrature::exp_sinh<mp::Real> exp_sinh(12);
  double worst_rule = 0;
  for (double s : {0.0, 3.0, 1e4})
    for (int k : {1, 4}) {
      const mp::Real S = s;
      auto f = [&](const mp::Real& u) {
        const mp::Real e = exp(-u * (S + u / 2));
        return e == 0 ? e : pow(u, k) * e;  // 0, not inf * 0, far out
      };
      const mp::Real adaptive = exp_sinh.integrate(f, mp::Real("1e-35"));
      worst_rule = std::max(worst_rule, static_cast<double>(abs(mp::integrate_gaussian_tail(f, S) / adaptive - 1)));
    }
  std::printf("Gauss-Legendre 40 on [0, U] vs adaptive exp_sinh: %.2g\n", worst_rule);
  EXPECT_LT(worst_rule, 1e-22);

  double worst_erfc = 0;
  for (double x : {-5.0, -0.7, 0.0, 1e-8, 0.3, 2.0, 7.5, 30.0, 300.0}) {
    const mp::Real X = x;
    worst_erfc = std::max(worst_erfc, static_cast<double>(abs(mp::erfc(X) / boost::math::erfc(X) - 1)));
    if (x != 0) worst_erfc = std::max(worst_erfc, static_cast<double>(abs(mp::erf(X) / boost::math::erf(X) - 1)));
  }
  std::printf("integral erf/erfc vs Boost.Math erf/erfc (50 digits): %.2g\n", worst_erfc);

  // The visible height density (1 + Lambda) C^Lambda c integrates to C^(1 + Lambda): int_0^inf of it at z - v
  // (one case: Boost's 50-digit erfc costs ~0.1 ms, and exp_sinh takes ~1500 nodes).
  const mp::Real z = 1, lambda = 25;
  auto density = [&](const mp::Real& v) {
    const mp::Real h = z - v, C = boost::math::erfc(-h / mp::kSqrt2) / 2;
    return C == 0 ? C : (1 + lambda) * exp(lambda * log(C)) * mp::normal_pdf(h);
  };
  const double height = static_cast<double>(
      abs(exp_sinh.integrate(density, mp::Real("1e-30")) / exp((1 + lambda) * mp::log_normal_cdf(z)) - 1));
  std::printf("visible height density integrated vs C^(1 + Lambda): %.2g\n", height);
  EXPECT_LT(height, 1e-22);
  EXPECT_LT(worst_erfc, 1e-22);

  // Cross-sections: the 20-point rule per piece against 40 points, across the kinks near the peak (u = 1e-5) and below
  // the horizon (where SG's sigma is 1e-20); one case each (a 40-point value costs up to 40 ms).
  auto r = [](const mp::Real& a, const mp::Real& b) { return static_cast<double>(abs(a / b - 1)); };
  const double worst_sigma = std::max({r(mp::ggx_sigma(0.01, 1e-5), mp::ggx_sigma<40>(0.01, 1e-5)),
                                       r(mp::kk_sigma(1 - 1e-6, -0.3), mp::kk_sigma<40>(1 - 1e-6, -0.3)),
                                       r(mp::sg_sigma(0.05, -0.3), mp::sg_sigma<40>(0.05, -0.3))});
  std::printf("cross-sections, 20- vs 40-point rule: %.2g\n", worst_sigma);
  EXPECT_LT(worst_sigma, 1e-19);

  double worst_slope = 0;
  const std::vector<SlopeCase> cases = quadrature_cases();
  for (std::size_t i = 0; i < cases.size(); i += 2) {  // every second case: the double rule is slow under ASan
    const SlopeCase& k = cases[i];
    const mp::VisibleSlope r = mp::visible_slope(k.mean_x, k.mean_y, k.var_x, k.var_y, k.c_xy, k.theta, k.phi);
    const SlopeMoments q = reference_visible_slope(k, Quadrature::GaussKronrod);
    const double tr = q.var_x + q.var_y;
    const double e =
        std::max({std::abs(double(r.log_N) - q.log_N), std::abs(double(r.mean_x) - q.mean_x) / std::sqrt(tr),
                  std::abs(double(r.mean_y) - q.mean_y) / std::sqrt(tr), std::abs(double(r.var_x) - q.var_x) / tr,
                  std::abs(double(r.var_y) - q.var_y) / tr, std::abs(double(r.c_xy) - q.c_xy) / tr});
    const Errors floor = input_floor(k, q, 2.2e-16);  // the double quadrature's own input rounding
    worst_slope = std::max(worst_slope, e / (1e-10 + floor.log_N + floor.mean + floor.cov));
  }
  std::printf("visible slope: 50-digit product rule vs double nested Gauss-Kronrod: worst/(1e-10 + floor) %.2g\n",
              worst_slope);
  EXPECT_LT(worst_slope, 1.0);
}

TEST(KernelAccuracy, SpecialFunctions) { expect_within_bounds(accuracy::special_function_rows(1)); }

TEST(KernelAccuracy, SmithMasking) { expect_within_bounds(accuracy::masking_rows(1)); }

TEST(KernelAccuracy, VisibleHeights) { expect_within_bounds(accuracy::visible_height_rows(1)); }

TEST(KernelAccuracy, BeckmannCrossSection) { expect_within_bounds(accuracy::beckmann_sigma_rows(1)); }

TEST(KernelAccuracy, GgxCrossSection) { expect_within_bounds(accuracy::ggx_sigma_rows(1)); }

TEST(KernelAccuracy, KagiwadaKalabaCrossSection) { expect_within_bounds(accuracy::kk_sigma_rows(1)); }

TEST(KernelAccuracy, SphericalGaussianCrossSection) { expect_within_bounds(accuracy::sg_sigma_rows(1)); }

TEST(KernelAccuracy, DiffractionTaylorTermCount) { expect_within_bounds(accuracy::taylor_rows(1)); }

TEST(KernelAccuracy, DiffractionChebyshevTransform) { expect_within_bounds(accuracy::chebyshev_transform_rows(1)); }

TEST(KernelAccuracy, VisibleSlopeIssue21Sweep) { expect_within_bounds(accuracy::visible_slope_issue_rows(1)); }

TEST(KernelAccuracy, VisibleSlopeWholeDomain) { expect_within_bounds(accuracy::visible_slope_domain_rows(1)); }

TEST(KernelAccuracy, VisibleSlopeExtremeInputs) { expect_within_bounds(accuracy::visible_slope_extreme_rows()); }

}  // namespace
