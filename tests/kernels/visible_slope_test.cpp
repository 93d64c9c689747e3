// visible_slope() of shaders/lib/visible_slope.glsl (float and double twins) against brute-force 2D
// quadrature of the defining integrals (reference_visible_slope.hpp, two independent rules), against
// weighted samples of p_s, and for its invariants over the extreme domain.
//
// Error measures and their input floor: visible_slope_cases.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "kernels/shared.hpp"
#include "reference_visible_slope.hpp"
#include "visible_slope_cases.hpp"

namespace visible_slope_test {

using namespace facet;
using test::Errors;
using test::errors;
using test::input_floor;
using test::kPi;
using test::quadrature_cases;
using test::rounded_to_float;
using test::SlopeCase;
using test::SlopeMoments;

TEST(VisibleSlope, QuadratureRulesAgreeAndKernelsMatchThem) {
  double worst_rules = 0;
  Errors worst64{0, 0, 0}, worst32{0, 0, 0};
  for (const SlopeCase& k : quadrature_cases()) {
    SCOPED_TRACE(::testing::Message() << "case " << k.mean_x << " " << k.mean_y << " " << k.var_x << " " << k.var_y
                                      << " " << k.c_xy << " theta " << k.theta << " phi " << k.phi);
    const SlopeMoments gk = test::reference_visible_slope(k, test::Quadrature::GaussKronrod);
    const SlopeMoments ts = test::reference_visible_slope(k, test::Quadrature::TanhSinh);
    struct {
      double log_N;
      glm::dvec2 mean;
      glm::dvec3 cov;
    } ts_as_result{ts.log_N, {ts.mean_x, ts.mean_y}, {ts.var_x, ts.var_y, ts.c_xy}};
    const Errors rules = errors(gk, ts_as_result);
    const Errors floor64 = input_floor(k, gk, 2.2e-16);
    EXPECT_LE(rules.log_N, 1e-10 + floor64.log_N);
    EXPECT_LE(rules.mean, 1e-10 + floor64.mean);
    EXPECT_LE(rules.cov, 1e-10 + floor64.cov);
    worst_rules = std::max({worst_rules, rules.log_N - floor64.log_N, rules.mean, rules.cov});

    const auto d = kernels::f64::visible_slope({k.mean_x, k.mean_y}, {k.var_x, k.var_y, k.c_xy}, k.theta, k.phi);
    const Errors e64 = errors(gk, d);
    EXPECT_LE(e64.log_N, 1e-9 + 4 * floor64.log_N);
    EXPECT_LE(e64.mean, 1e-9 + 4 * floor64.mean);
    EXPECT_LE(e64.cov, 1e-9 + 4 * floor64.cov);
    worst64 = {std::max(worst64.log_N, e64.log_N), std::max(worst64.mean, e64.mean), std::max(worst64.cov, e64.cov)};

    const SlopeCase kf = rounded_to_float(k);
    const SlopeMoments gkf = test::reference_visible_slope(kf, test::Quadrature::GaussKronrod);
    const auto f =
        kernels::f32::visible_slope({float(kf.mean_x), float(kf.mean_y)},
                                    {float(kf.var_x), float(kf.var_y), float(kf.c_xy)}, float(kf.theta), float(kf.phi));
    const Errors e32 = errors(gkf, f);
    const Errors floor32 = input_floor(kf, gkf, 1.2e-7);
    EXPECT_LE(e32.log_N, 2e-4 + 4 * floor32.log_N);
    EXPECT_LE(e32.mean, 2e-4 + 4 * floor32.mean);
    EXPECT_LE(e32.cov, 2e-4 + 4 * floor32.cov);
    worst32 = {std::max(worst32.log_N, e32.log_N), std::max(worst32.mean, e32.mean), std::max(worst32.cov, e32.cov)};
  }
  std::printf("rules disagree by %.2g (beyond the double input floor)\n", worst_rules);
  std::printf("worst f64: logN %.2g mean %.2g cov %.2g\n", worst64.log_N, worst64.mean, worst64.cov);
  std::printf("worst f32: logN %.2g mean %.2g cov %.2g\n", worst32.log_N, worst32.mean, worst32.cov);
}

// docs/errata.md#visible-slope-normal-incidence: at theta = 0 exactly, D_s = p_s and N = 1.
TEST(VisibleSlope, NormalIncidenceIsExactlyTheSlopeLaw) {
  const auto d = kernels::f64::visible_slope({1, 0}, {1, 1, 0}, 0.0, 0.0);  // Table 3 row 1
  EXPECT_NEAR(d.N, 1.0, 1e-15);
  EXPECT_NEAR(d.mean.x, 1.0, 1e-14);
  EXPECT_NEAR(d.mean.y, 0.0, 1e-15);
  EXPECT_NEAR(d.cov.x, 1.0, 1e-14);
  EXPECT_NEAR(d.cov.y, 1.0, 1e-14);
  EXPECT_NEAR(d.cov.z, 0.0, 1e-15);
  const auto f = kernels::f32::visible_slope({0.3f, -2.0f}, {1e-10f, 1e4f, 0.5f}, 0.0f, 1.0f);
  EXPECT_NEAR(f.N, 1.0f, 1e-6f);
  EXPECT_NEAR(f.mean.x, 0.3f, 1e-6f);
  EXPECT_NEAR(f.mean.y, -2.0f, 1e-6f);
  EXPECT_NEAR(f.cov.y, 1e4f, 1e-2f);
}

// Results are finite and the covariance is symmetric PSD over the whole domain, in both precisions.
template <class R, class Kernel>
void sweep_domain(Kernel visible_slope) {
  const R thetas[] = {R(0), R(1e-7), R(0.3), R(1.0), R(1.5), R(1.5707962)};
  const R vars[] = {R(1e-10), R(1e-3), R(1), R(1e4)};
  const R rhos[] = {R(-(1 - 1e-6)), R(-0.5), R(0), R(0.9), R(1 - 1e-6)};
  const R means[] = {R(-1e4), R(-30), R(-1), R(0), R(0.5), R(3), R(1e4)};
  int count = 0;
  for (R theta : thetas)
    for (R vx : vars)
      for (R vy : vars)
        for (R rho : rhos)
          for (R mx : means)
            for (R phi : {R(0), R(0.8), R(-2.5)}) {
              const R cxy = rho * std::sqrt(vx * vy);
              const auto d = visible_slope(mx, R(0.3) * mx, vx, vy, cxy, theta, phi);
              ++count;
              ASSERT_TRUE(std::isfinite(d.log_N) && std::isfinite(d.N)) << mx << " " << vx << " " << vy << " " << theta;
              ASSERT_TRUE(std::isfinite(d.mean.x) && std::isfinite(d.mean.y));
              ASSERT_TRUE(std::isfinite(d.cov.x) && std::isfinite(d.cov.y) && std::isfinite(d.cov.z));
              ASSERT_GE(d.cov.x, R(0));
              ASSERT_GE(d.cov.y, R(0));
              ASSERT_LE(d.cov.z * d.cov.z, d.cov.x * d.cov.y * R(1 + 1e-5));
            }
  EXPECT_GT(count, 10000);
}

TEST(VisibleSlope, FiniteAndPsdOverTheExtremeDomain) {
  sweep_domain<double>([](double mx, double my, double vx, double vy, double c, double theta, double phi) {
    return kernels::f64::visible_slope({mx, my}, {vx, vy, c}, theta, phi);
  });
  sweep_domain<float>([](float mx, float my, float vx, float vy, float c, float theta, float phi) {
    return kernels::f32::visible_slope({mx, my}, {vx, vy, c}, theta, phi);
  });
}

// Rotating the slope law and the view azimuth by alpha rotates D_s by alpha.
TEST(VisibleSlope, CovariantUnderRotation) {
  const double alpha = 0.7, ca = std::cos(alpha), sa = std::sin(alpha);
  const glm::dvec2 mean(0.4, -0.2);
  const glm::dmat2 sigma(0.3, 0.1, 0.1, 0.8), rot(ca, sa, -sa, ca);
  const glm::dmat2 sigma_r = rot * sigma * glm::transpose(rot);
  for (double theta : {0.2, 1.0, 1.5}) {
    const auto d = kernels::f64::visible_slope(mean, {sigma[0][0], sigma[1][1], sigma[0][1]}, theta, 0.3);
    const auto r =
        kernels::f64::visible_slope(rot * mean, {sigma_r[0][0], sigma_r[1][1], sigma_r[0][1]}, theta, 0.3 + alpha);
    const glm::dmat2 cov(d.cov.x, d.cov.z, d.cov.z, d.cov.y);
    const glm::dmat2 cov_r = rot * cov * glm::transpose(rot);
    const glm::dvec2 mean_r = rot * d.mean;
    EXPECT_NEAR(r.log_N, d.log_N, 1e-13);
    EXPECT_NEAR(r.mean.x, mean_r.x, 1e-13);
    EXPECT_NEAR(r.mean.y, mean_r.y, 1e-13);
    EXPECT_NEAR(r.cov.x, cov_r[0][0], 1e-13);
    EXPECT_NEAR(r.cov.y, cov_r[1][1], 1e-13);
    EXPECT_NEAR(r.cov.z, cov_r[0][1], 1e-13);
  }
}

// Slopes actually visible on a sampled Gaussian microsurface: slopes drawn from p_s, each facet
// weighted by its projected area max(0, omega.n)/n_z = max(0, W(s)) (eq. 12). The weighted mean,
// covariance and mean weight (= N) must match the kernel within 5 Monte Carlo standard errors.
TEST(VisibleSlope, MatchesWeightedSlopeSamples) {
  const SlopeCase cases[] = {
      {1, 0, 1, 1, 0, 1.56, 0}, {0.3, -0.2, 0.2, 0.1, 0.05, 0.9, 0.4}, {1.5, 0.5, 0.5, 0.3, -0.2, 0.8, 0.2}};
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  for (const SlopeCase& k : cases) {
    const double l11 = std::sqrt(k.var_x), l21 = k.c_xy / l11, l22 = std::sqrt(k.var_y - l21 * l21);
    const double wx = -std::sin(k.theta) * std::cos(k.phi), wy = -std::sin(k.theta) * std::sin(k.phi);
    const int n = 400000;
    double sw = 0, sw2 = 0, mx = 0, my = 0, xx = 0, yy = 0, xy = 0;
    std::vector<double> xs(n), ys(n), ws(n);
    for (int i = 0; i < n; ++i) {
      const double z1 = normal(rng), z2 = normal(rng);
      xs[i] = k.mean_x + l11 * z1;
      ys[i] = k.mean_y + l21 * z1 + l22 * z2;
      ws[i] = std::max(0.0, xs[i] * wx + ys[i] * wy + std::cos(k.theta));
      sw += ws[i];
      sw2 += ws[i] * ws[i];
      mx += ws[i] * xs[i];
      my += ws[i] * ys[i];
    }
    mx /= sw;
    my /= sw;
    for (int i = 0; i < n; ++i) {
      xx += ws[i] * (xs[i] - mx) * (xs[i] - mx);
      yy += ws[i] * (ys[i] - my) * (ys[i] - my);
      xy += ws[i] * (xs[i] - mx) * (ys[i] - my);
    }
    xx /= sw;
    yy /= sw;
    xy /= sw;
    const double N = sw / n, n_eff = sw * sw / sw2;  // effective sample size of the weighted mean
    const auto d = kernels::f64::visible_slope({k.mean_x, k.mean_y}, {k.var_x, k.var_y, k.c_xy}, k.theta, k.phi);
    EXPECT_NEAR(d.N, N, 5 * std::sqrt((sw2 / n - N * N) / n));
    EXPECT_NEAR(d.mean.x, mx, 5 * std::sqrt(xx / n_eff));
    EXPECT_NEAR(d.mean.y, my, 5 * std::sqrt(yy / n_eff));
    // Standard error of a variance ~ var sqrt(2/n_eff) (Gaussian-like); 6 of them, D_s is skewed.
    EXPECT_NEAR(d.cov.x, xx, 6 * xx * std::sqrt(2 / n_eff));
    EXPECT_NEAR(d.cov.y, yy, 6 * yy * std::sqrt(2 / n_eff));
    EXPECT_NEAR(d.cov.z, xy, 6 * std::sqrt(xx * yy) * std::sqrt(2 / n_eff));
  }
}

}  // namespace visible_slope_test
