// The reference's exact transform (piecewise Chebyshev interpolation in x = k w h_s through exact
// FFT values) against ExactTransform::bins (two FFTs at that very x) at random x: every band bin
// within the proven remainder bound 2 sqrt 2 (L/4)^n / n! plus double rounding.
#include <gtest/gtest.h>

#include <complex>
#include <iostream>
#include <random>

#include "common/error.hpp"
#include "diffraction/chebyshev_transform.hpp"
#include "diffraction_cases.hpp"

namespace facet {
namespace {

using diffraction::ChebyshevTransform;
using diffraction::ExactTransform;

// Rounding of the node values (FFTs in double, |p_j| <= 1) times the Lebesgue constant of 16
// Chebyshev points ((2/pi) ln 16 + 1 < 3), with room for the barycentric sums: 1e-13.
constexpr double kRounding = 1e-13;

double worst_bin_error(const diffraction::Grating& g, const diffraction::SpectralTables& t,
                       const ChebyshevTransform& cheb, double x) {
  const ExactTransform exact(g, t);
  const ExactTransform::Bins direct = exact.bins(x);
  const ChebyshevTransform::AtX interpolated = cheb.at(x);
  double worst = 0.0;
  for (int jy = -t.J; jy <= t.J; ++jy)
    for (int jx = -t.J; jx <= t.J; ++jx)
      worst = std::max(worst, std::abs(interpolated.bin(jx, jy) - direct.at(jx, jy)));
  return worst;
}

TEST(ChebyshevTransform, RemainderBoundIsBelowDoubleNoiseLevel) {
  const auto g = test::grating(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":300,"size_um":4,"samples":32})");
  const auto t = diffraction::build_spectral_tables(g, {.lambda_min_nm = 360, .tolerance = 1e-3, .terms = 1});
  const ChebyshevTransform cheb(g, t);
  // Pieces of length <= 4: 2 sqrt 2 / 16! = 1.35e-13.
  EXPECT_LE(cheb.error_bound(), 1.36e-13);
  EXPECT_NEAR(cheb.x_max(), t.x_max, 0.0);
}

TEST(ChebyshevTransform, MatchesTheExactBinsAtRandomX) {
  // A tall sinusoid (x_max = 2 k_max h_s = 10.5: three pieces) and snake-like fingers (one piece).
  for (
      const char* json :
      {R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":300,"size_um":4,"samples":32})",
       R"({"type":"fingers","period_nm":800,"amplitude_nm":90,"size_um":3.2,"samples":64,"finger_length_nm":1600,"coherence_um":1.6})"}) {
    const auto g = test::grating(json);
    const auto t = diffraction::build_spectral_tables(g, {.lambda_min_nm = 360, .tolerance = 1e-3, .terms = 1});
    const ChebyshevTransform cheb(g, t);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> uniform(-t.x_max, 0.0);
    std::vector<double> xs = {-t.x_max, 0.0, -1e-9 * t.x_max};
    for (int i = 0; i < 24; ++i) xs.push_back(uniform(rng));
    double worst = 0.0;
    for (double x : xs) worst = std::max(worst, worst_bin_error(g, t, cheb, x));
    EXPECT_LE(worst, cheb.error_bound() + kRounding) << json;
    RecordProperty("worst_bin_error", std::to_string(worst));
    std::cout << "[ measured ] worst |interpolated - exact bin| = " << worst << " (bound "
              << cheb.error_bound() + kRounding << ")\n";
  }
}

TEST(ChebyshevTransform, BrdfMatchesTheExactTransform) {
  const auto g = test::grating(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":150,"size_um":4,"samples":32})");
  const auto t = diffraction::build_spectral_tables(g, {.lambda_min_nm = 360, .tolerance = 1e-10, .terms = 1});
  const ChebyshevTransform cheb(g, t);
  const ExactTransform exact(g, t);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> side(-0.7, 0.7), lambda(360.0, 830.0);
  for (int i = 0; i < 200; ++i) {
    const diffraction::DiffractionQuery q{test::direction(side(rng), side(rng)), test::direction(side(rng), side(rng)),
                                          lambda(rng)};
    const double a = cheb.evaluate(q).brdf, b = exact.evaluate(q).brdf;
    // |S| moves by at most W times the bin error; the BRDF is quadratic in S: relative 1e-9 is generous.
    EXPECT_NEAR(a, b, 1e-9 * std::max(b, 1e-3)) << i;
  }
}

TEST(ChebyshevTransform, RefusesXOutsideItsRange) {
  const auto g = test::grating(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":100,"size_um":4,"samples":32})");
  const auto t = diffraction::build_spectral_tables(g, {.lambda_min_nm = 360, .tolerance = 1e-3, .terms = 1});
  const ChebyshevTransform cheb(g, t);
  EXPECT_THROW(cheb.at(-1.01 * t.x_max), Error);
  EXPECT_THROW(cheb.at(1e-3), Error);
  // lambda below the tables' 360 nm makes k w h_s too large.
  EXPECT_THROW(cheb.evaluate({{0, 0, 1}, {0, 0, 1}, 300.0}), Error);
}

}  // namespace
}  // namespace facet
