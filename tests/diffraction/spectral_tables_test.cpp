// The spectral tables against a direct DFT sum, and the term count and window radius against
// the bounds they implement.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "common/error.hpp"
#include "diffraction_cases.hpp"
#include "kernels/shared.hpp"

namespace facet {
namespace {

using diffraction::build_spectral_tables;

// H_n(j) = (1/M^2) sum_x ((h - mean)/h_s)^n exp(+i 2 pi j.x / M), summed directly in double.
std::complex<double> direct_dft(const diffraction::Grating& g, const diffraction::SpectralTables& t, int n, int jx,
                                int jy) {
  const int M = g.samples;
  std::complex<double> sum = 0.0;
  for (int y = 0; y < M; ++y)
    for (int x = 0; x < M; ++x) {
      const double h = (g.height_nm[y * M + x] - t.mean_nm) / t.hs_nm;
      sum += std::pow(h, n) * std::polar(1.0, 2.0 * test::kPi * (jx * x + jy * y) / M);
    }
  return sum / double(M * M);
}

// Every stored bin, including the conjugated half j_y < 0, of an asymmetric 2-D pattern (fingers)
// and of a rectangular grating, on 16 x 16 and 24 x 24 patches. Both sides are double; 1e-13 is a
// few hundred ulps of the O(1) coefficients, the rounding of an M^2-term sum.
TEST(SpectralTables, MatchTheDirectDftSum) {
  for (
      const char* json :
      {R"({"type":"fingers","period_nm":1000,"amplitude_nm":200,"size_um":4,"samples":16,"finger_length_nm":1000,"duty":0.6})",
       R"({"type":"rectangular","period_nm":1000,"amplitude_nm":120,"size_um":3,"samples":24,"duty":0.3})"}) {
    const auto g = test::grating(json);
    const auto t = build_spectral_tables(g, {.lambda_min_nm = 300.0});
    ASSERT_GE(t.N, 3);
    double worst = 0.0;
    for (int n = 0; n < t.N; ++n)
      for (int jy = -t.J; jy <= t.J; ++jy)
        for (int jx = -t.J; jx <= t.J; ++jx) {
          const auto e = kernels::f64::diffraction_table_entry(n, jx, jy, t.J, t.stored_terms);
          ASSERT_TRUE(e.valid);
          const std::complex<double> stored =
              e.conjugate ? std::conj(t.coefficients[e.index]) : t.coefficients[e.index];
          worst = std::max(worst, std::abs(stored - direct_dft(g, t, n, jx, jy)));
        }
    EXPECT_LT(worst, 1e-13) << json;
    // The height is mean-free and normalised: H_0 = delta_j0, H_1(0) = 0, max |h| = h_s.
    EXPECT_NEAR(std::abs(t.coefficients[kernels::f64::diffraction_table_entry(1, 0, 0, t.J, t.stored_terms).index]),
                0.0, 1e-15);
  }
}

// N is the first count whose Lagrange remainder x^N / N! is within the tolerance (docs/errata.md#taylor-bound): the
// bound holds at N and fails at N - 1; and the bound really bounds |e^{ix} - sum_{n<N} (ix)^n/n!|.
TEST(SpectralTables, TaylorTermCountIsTheTightLagrangeBound) {
  for (double x : {0.1, 1.0, 1.5 * test::kPi, 4.0 * test::kPi})
    for (double tol : {1e-3, 1e-6, 1e-10}) {
      const int N = diffraction::taylor_term_count(x, tol);
      auto remainder_bound = [&](int n) { return std::exp(n * std::log(x) - std::lgamma(n + 1.0)); };
      EXPECT_LE(remainder_bound(N), tol);
      if (N > 1) {
        EXPECT_GT(remainder_bound(N - 1), tol);
      }
      std::complex<double> sum = 0.0, term = 1.0;
      for (int n = 0; n < N; ++n, term *= std::complex<double>(0.0, x) / double(n)) sum += term;
      EXPECT_LE(std::abs(sum - std::polar(1.0, x)), remainder_bound(N) * (1 + 1e-9) + 1e-13) << x << " " << tol;
    }
  // The paper's example (x = 1.5 pi, C.6) needs 25 terms with its loose bound at 1e-7; the tight one needs fewer.
  EXPECT_LT(diffraction::taylor_term_count(1.5 * test::kPi, 8.815e-8), 25);
}

TEST(SpectralTables, WindowRadiusCoversTheTolerance) {
  for (double ratio : {0.25, 0.5, 1.0, 3.0})
    for (double tol : {1e-3, 1e-6}) {
      const double T = 1000.0, sigma = ratio * T;
      const int r = diffraction::window_radius(T, sigma, tol);
      const double c = 2.0 * test::kPi * sigma / T;
      // The first bin left out is at least r + 1/2 bins from the frequency; with r - 1 it is not.
      EXPECT_LE(std::exp(-0.5 * c * c * (r + 0.5) * (r + 0.5)), tol);
      if (r > 0) {
        EXPECT_GT(std::exp(-0.5 * c * c * (r - 0.5) * (r - 0.5)), tol);
      }
    }
}

TEST(SpectralTables, BadRangesAreErrors) {
  const auto g = test::grating(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":100,"size_um":4,"samples":16})");
  EXPECT_THROW(build_spectral_tables(g, {.lambda_min_nm = 0.0}), Error);
  EXPECT_THROW(build_spectral_tables(g, {.w_max = 3.0}), Error);
  EXPECT_THROW(build_spectral_tables(g, {.tolerance = 0.0}), Error);
  // A grating so tall that the series would need more than 64 terms.
  const auto tall =
      test::grating(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":5000,"size_um":4,"samples":16})");
  EXPECT_THROW(build_spectral_tables(tall), Error);
}

}  // namespace
}  // namespace facet
