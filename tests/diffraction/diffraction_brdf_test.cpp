// Stam's diffraction BRDF on the CPU in double, against physics and against itself computed
// another way: the grating equation, Bessel efficiencies of a thin sinusoidal phase grating, energy
// of a flat mirror, a brute-force windowed transform, the exact transform, reciprocity and the
// grazing limit.
#include <gtest/gtest.h>

#include <boost/math/special_functions/bessel.hpp>
#include <cmath>
#include <complex>
#include <random>

#include "diffraction/exact_transform.hpp"
#include "diffraction_cases.hpp"

namespace facet {
namespace {

using diffraction::DiffractionQuery;
using diffraction::evaluate_taylor;
using test::direction;
using test::kPi;

// Period 1300 nm, 20 periods per patch, 16 samples per period, coherence = patch.
const char* kSinusoid =
    R"({"type":"sinusoid","period_nm":1300,"amplitude_nm":80,"size_um":26,"samples":320,"coherence_um":26})";
// The same with a coherence area of 100 patches: lobes of width 1/(k sigma) ~ 3e-5.
const char* kSinusoidCoherent =
    R"({"type":"sinusoid","period_nm":1300,"amplitude_nm":80,"size_um":26,"samples":320,"coherence_um":2600})";

// The order-m peak of a 1-D grating of period L lies where k u = 2 pi m / L (the grating
// equation sin theta_r = -sin theta_i - m lambda / L in the plane of incidence). A scan of wr.x in
// steps of 2e-7 around each predicted order over the visible range must find the maximum of P2
// within 2 steps. The smooth factors (J_m(k w a)^2, G / w^2) of slope d ln/dx ~ 10 shift a
// Gaussian lobe of variance s^2 = 1/(2 k^2 sigma^2) <= 1e-9 by ~1e-8, far below a step.
TEST(DiffractionBrdf, PeaksFollowTheGratingEquation1D) {
  const auto g = test::grating(kSinusoidCoherent);
  const auto t = diffraction::build_spectral_tables(g);
  const glm::dvec3 wi = direction(std::sin(0.5), 0.0);
  int peaks = 0;
  for (double lambda : {400.0, 480.0, 550.0, 620.0, 700.0})
    for (int m = -3; m <= 3; ++m) {
      const double predicted = -wi.x - m * lambda / 1300.0;
      if (std::abs(predicted) > 0.95) continue;
      const double step = 2e-7;
      double best = -1.0, best_x = 0.0;
      for (int s = -400; s <= 400; ++s) {
        const double x = predicted + s * step;
        const double P2 = evaluate_taylor(t, {wi, direction(x, 0.0), lambda}).P2;
        if (P2 > best) best = P2, best_x = x;
      }
      EXPECT_NEAR(best_x, predicted, 2 * step) << "lambda " << lambda << " order " << m;
      ++peaks;
    }
  EXPECT_GE(peaks, 20);
}

// A crossed grating with periods 1000 nm (x) and 1500 nm (y): peaks at
// (u, v) = (m lambda / 1000, n lambda / 1500), found by a 2-D scan in steps of 1e-6 (coherence
// 1.2 mm: lobes <= 1e-4 wide, s^2 <= 5e-9, shifted by the smooth factors by ~5e-8).
TEST(DiffractionBrdf, PeaksFollowTheGratingEquation2D) {
  const auto g = test::grating(
      R"({"type":"crossed","period_nm":[1000,1500],"amplitude_nm":100,"size_um":12,"samples":192,"coherence_um":1200})");
  const auto t = diffraction::build_spectral_tables(g);
  const glm::dvec3 wi = direction(0.2, -0.1);
  for (double lambda : {420.0, 560.0, 680.0})
    for (auto [m, n] : {std::pair{1, 0}, {0, 1}, {1, 1}, {-1, 1}, {0, -1}}) {
      const glm::dvec2 predicted(-wi.x - m * lambda / 1000.0, -wi.y - n * lambda / 1500.0);
      const double step = 1e-6;
      double best = -1.0;
      glm::dvec2 best_xy(0.0);
      for (int sy = -30; sy <= 30; ++sy)
        for (int sx = -30; sx <= 30; ++sx) {
          const glm::dvec2 xy = predicted + step * glm::dvec2(sx, sy);
          const double P2 = evaluate_taylor(t, {wi, direction(xy.x, xy.y), lambda}).P2;
          if (P2 > best) best = P2, best_xy = xy;
        }
      EXPECT_NEAR(best_xy.x, predicted.x, step) << lambda << " " << m << " " << n;
      EXPECT_NEAR(best_xy.y, predicted.y, step) << lambda << " " << m << " " << n;
    }
}

// A thin sinusoidal phase grating h = a sin(2 pi x / L) has p = exp(i x sin) = sum_m J_m(x) e^{i m ...}
// with x = k w a, so at the order-m peak |S| = |J_m(k w a)| (other orders lie 20 bins away, weight
// exp(-2 pi^2 400)). Sampled at 16 points per period, order m also receives the aliased orders
// m + 16 l: the DFT coefficient is sum_l J_{m+16l}(x) exactly, which the exact path must reproduce
// to 1e-12 (rounding of the FFT); the Taylor path within W * tolerance (1e-4, the Lagrange bound).
TEST(DiffractionBrdf, OrderPowersAreBesselEfficiencies) {
  const auto g = test::grating(kSinusoid);
  const auto t = diffraction::build_spectral_tables(g);
  const diffraction::ExactTransform exact(g, t);
  const double W = test::window_weight_bound(t);
  for (double theta_i : {0.0, 0.4, 0.9})
    for (double lambda : {400.0, 550.0, 700.0})
      for (int m = -4; m <= 4; ++m) {
        const glm::dvec3 wi = direction(std::sin(theta_i), 0.0);
        const double x_r = -wi.x - m * lambda / 1300.0;
        if (std::abs(x_r) > 0.99) continue;
        const DiffractionQuery q{wi, direction(x_r, 0.0), lambda};
        const double w = -(q.wi.z + q.wr.z);
        const double x = 2 * kPi / lambda * w * 80.0;
        double aliased = 0.0;
        for (int l = -3; l <= 3; ++l) aliased += boost::math::cyl_bessel_j(m + 16 * l, x);
        const double efficiency = std::abs(boost::math::cyl_bessel_j(m, x));
        EXPECT_NEAR(test::field_magnitude(evaluate_taylor(t, q).P2, t.sigma_nm), efficiency, W * 1e-4)
            << theta_i << " " << lambda << " " << m;
        EXPECT_NEAR(test::field_magnitude(exact.evaluate(q).P2, t.sigma_nm), std::abs(aliased), 1e-12)
            << theta_i << " " << lambda << " " << m;
      }
}

// A flat surface reflects all of Schlick's R (F^2 read as the reflectance) into the mirror lobe:
// integral of BRDF cos theta_r d omega_r = integral of BRDF d(wr.x) d(wr.y) = R(theta_i). The lobe
// has width 1/(k sigma) = 1/1257; over +-8 widths with 161^2 midpoints the quadrature error is
// below 1e-6. What remains is the variation of G / w^2 and of the Jacobian across the lobe, which
// grows toward grazing: measured 1.5e-3 at theta_i = 1.3 for k sigma = 251 and falling as 1/(k sigma).
TEST(DiffractionBrdf, FlatMirrorReflectsSchlickReflectance) {
  const auto g = test::grating(
      R"({"type":"sinusoid","period_nm":5000,"amplitude_nm":0,"size_um":20,"samples":64,"ior":1.5,"coherence_um":100})");
  const auto t = diffraction::build_spectral_tables(g);
  const double lambda = 500.0, width = 1.0 / (2 * kPi / lambda * t.sigma_nm);
  for (double theta_i : {0.0, 0.5, 1.0, 1.3}) {
    const glm::dvec3 wi = direction(std::sin(theta_i), 0.0);
    const int n = 161;
    const double h = 16.0 * width / n;
    double albedo = 0.0;
    for (int iy = 0; iy < n; ++iy)
      for (int ix = 0; ix < n; ++ix) {
        const glm::dvec2 xy = glm::dvec2(-wi.x, -wi.y) + h * glm::dvec2(ix + 0.5 - n / 2.0, iy + 0.5 - n / 2.0);
        albedo += evaluate_taylor(t, {wi, direction(xy.x, xy.y), lambda}).brdf * h * h;
      }
    const double R = t.R0 + (1 - t.R0) * std::pow(1 - std::cos(theta_i), 5);
    EXPECT_NEAR(albedo / R, 1.0, 1e-3) << theta_i;
  }
}

// The windowed transform of the tiled patch, S = (1 / (2 pi sigma^2)) sum over the infinite lattice
// of g(x) p(x) e^{i alpha.x} Delta^2, summed by brute force over every sample within 9 sigma,
// against the exact path's bin sum (normalisation of P2 = 4 pi sigma^2 |S|^2). Tolerance: the
// window truncation of the bin sum (1e-4 relative weights, W of them).
TEST(DiffractionBrdf, WindowedTransformMatchesBruteForceLatticeSum) {
  const auto g = test::grating(
      R"({"type":"fingers","period_nm":500,"amplitude_nm":60,"size_um":2,"samples":16,"finger_length_nm":500,"coherence_um":1})");
  const auto t = diffraction::build_spectral_tables(g);
  const diffraction::ExactTransform exact(g, t);
  const int M = g.samples;
  const double delta = g.sample_nm, sigma = t.sigma_nm;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uni(-0.6, 0.6);
  for (int trial = 0; trial < 12; ++trial) {
    const DiffractionQuery q{direction(uni(rng), uni(rng)), direction(uni(rng), uni(rng)), 450.0 + 20 * trial};
    const double k = 2 * kPi / q.lambda_nm, w = -(q.wi.z + q.wr.z);
    const glm::dvec2 alpha = -k * glm::dvec2(q.wi.x + q.wr.x, q.wi.y + q.wr.y);
    const int reach = static_cast<int>(9 * sigma / delta);
    std::complex<double> S = 0.0;
    for (int y = -reach; y <= reach; ++y)
      for (int x = -reach; x <= reach; ++x) {
        const double h = g.height_nm[((y % M + M) % M) * M + (x % M + M) % M] - t.mean_nm;
        const double r2 = (x * x + y * y) * delta * delta;
        S += std::exp(-r2 / (2 * sigma * sigma)) * std::polar(1.0, k * w * h + (alpha.x * x + alpha.y * y) * delta);
      }
    S *= delta * delta / (2 * kPi * sigma * sigma);
    EXPECT_NEAR(test::field_magnitude(exact.evaluate(q).P2, sigma), std::abs(S), 1e-4 * test::window_weight_bound(t))
        << trial;
  }
}

// The Taylor sum against the exact transform for growing k w h_s (mean-free heights), in double.
// |S_taylor - S_exact| <= W x^N / N! (<= W tolerance): the remainder bound of docs/errata.md#taylor-bound.
TEST(DiffractionBrdf, TaylorSumMatchesExactTransformForGrowingHeights) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uni(-0.7, 0.7);
  for (double amplitude : {10.0, 60.0, 200.0, 400.0})
    for (double tol : {1e-4, 1e-8}) {
      const auto g = test::grating(
          R"({"type":"fingers","period_nm":1000,"size_um":4,"samples":64,"finger_length_nm":1000,"amplitude_nm":)" +
          std::to_string(amplitude) + "}");
      const auto t = diffraction::build_spectral_tables(g, {.lambda_min_nm = 400.0, .tolerance = tol});
      const diffraction::ExactTransform exact(g, t);
      const double bound = test::window_weight_bound(t) * tol;
      double worst = 0.0;
      for (int trial = 0; trial < 10; ++trial) {
        const DiffractionQuery q{direction(uni(rng), uni(rng)), direction(uni(rng), uni(rng)), 400.0 + 30 * trial};
        const double a = test::field_magnitude(evaluate_taylor(t, q).P2, t.sigma_nm);
        const double b = test::field_magnitude(exact.evaluate(q).P2, t.sigma_nm);
        worst = std::max(worst, std::abs(a - b));
      }
      EXPECT_LE(worst, bound) << "amplitude " << amplitude << " x_max " << t.x_max << " N " << t.N;
    }
}

// The sign of the transform (B.7, e^{+i k (u x + v y)}): a sawtooth rising along +x has facets whose
// normals lean toward -x, so at normal incidence the facets mirror light toward -x, i.e. into the
// order m = +1 (wr.x = -lambda / L) rather than m = -1. With the opposite sign the two would swap.
// Blazed with a = 250 nm at lambda = 500 nm, period L = 640 nm (4 per patch, 64 samples each): the
// order powers are sinc^2((phi +- 2 pi)/2) with phi = k w a = -5.10, i.e. 0.88 for m = +1 and 0.0098 for m = -1.
// The same along y (rows), which a grating seen from below mirrors unless its frame turns both axes (eq. R1 of
// docs/diffraction.md); a sawtooth falling along +y fails the check.
TEST(DiffractionBrdf, SawtoothSendsLightWhereItsFacetsMirrorIt) {
  for (int axis = 0; axis < 2; ++axis) {
    diffraction::Grating g;
    g.samples = 256;
    g.sample_nm = 10.0;
    g.coherence_nm = 2560.0;
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x) g.height_nm.push_back(250.0 * ((axis == 0 ? x : y) % 64) / 64.0);
    const auto t = diffraction::build_spectral_tables(g);
    const diffraction::ExactTransform exact(g, t);
    const glm::dvec3 normal(0, 0, 1);
    const double toward_minus = -500.0 / 640.0;  // the facets' mirror direction's component along the axis
    const DiffractionQuery plus{normal, axis == 0 ? direction(toward_minus, 0.0) : direction(0.0, toward_minus), 500.0};
    const DiffractionQuery minus{normal, axis == 0 ? direction(-toward_minus, 0.0) : direction(0.0, -toward_minus),
                                 500.0};
    EXPECT_GT(evaluate_taylor(t, plus).P2, 10 * evaluate_taylor(t, minus).P2) << "axis " << axis;
    EXPECT_GT(exact.evaluate(plus).P2, 10 * exact.evaluate(minus).P2) << "axis " << axis;
  }
}

// Swapping light and viewer leaves (u, v, w), G and the half vector unchanged.
TEST(DiffractionBrdf, IsReciprocal) {
  const auto g = test::grating(
      R"({"type":"fingers","period_nm":800,"amplitude_nm":90,"size_um":8,"samples":128,"finger_length_nm":2000})");
  const auto t = diffraction::build_spectral_tables(g);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(-0.7, 0.7);
  for (int trial = 0; trial < 200; ++trial) {
    const glm::dvec3 a = direction(uni(rng), uni(rng)), b = direction(uni(rng), uni(rng));
    const double lambda = 380 + 2 * trial;
    const auto ab = evaluate_taylor(t, {a, b, lambda}), ba = evaluate_taylor(t, {b, a, lambda});
    EXPECT_NEAR(ab.brdf, ba.brdf, 1e-12 * ab.brdf + 1e-300);
    EXPECT_EQ(ab.P2, ba.P2);
  }
}

// docs/errata.md#grazing-singularity: B.12 is singular as w -> 0 (both directions grazing). Over a grid of the whole
// hemisphere pair domain including z = 0 exactly, BRDF and P2 are finite and >= 0, and a direction
// at z = 1e-12 gives the same value as z = 0 (the floor at 1/(k sigma) makes the limit continuous).
TEST(DiffractionBrdf, FiniteOnTheWholeDomainIncludingGrazing) {
  const auto g = test::grating(
      R"({"type":"rectangular","period_nm":700,"amplitude_nm":150,"size_um":7,"samples":140,"duty":0.4})");
  const auto t = diffraction::build_spectral_tables(g);
  const double e = 1e-12;
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 16; ++j)
      for (int k = 0; k <= 8; ++k) {
        const double theta_i = kPi / 2 * i / 8, theta_r = kPi / 2 * k / 8, phi = 2 * kPi * j / 16;
        const glm::dvec3 wi(std::sin(theta_i), 0.0, i == 8 ? 0.0 : std::cos(theta_i));
        const glm::dvec3 wr(std::sin(theta_r) * std::cos(phi), std::sin(theta_r) * std::sin(phi),
                            k == 8 ? 0.0 : std::cos(theta_r));
        for (double lambda : {360.0, 830.0}) {
          const auto v = evaluate_taylor(t, {wi, wr, lambda});
          ASSERT_TRUE(std::isfinite(v.brdf) && v.brdf >= 0.0) << i << " " << j << " " << k;
          ASSERT_TRUE(std::isfinite(v.P2) && v.P2 >= 0.0);
        }
      }
  const glm::dvec3 wi(1.0, 0.0, 0.0), wr(-0.6, 0.8, 0.0);
  const auto at_zero = evaluate_taylor(t, {wi, wr, 500.0});
  const auto near_zero =
      evaluate_taylor(t, {glm::normalize(wi + glm::dvec3(0, 0, e)), glm::normalize(wr + glm::dvec3(0, 0, e)), 500.0});
  EXPECT_NEAR(near_zero.brdf, at_zero.brdf, 1e-9 * at_zero.brdf + 1e-300);
}

}  // namespace
}  // namespace facet
