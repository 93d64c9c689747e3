// gaussian_masking.glsl: Smith Lambda against the centred Beckmann closed form, its consistency with the
// visible slope normalisation N, height-correlated G2, and sampling of the visible heights C^(1+Lambda).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "kernels/shared.hpp"
#include "support/chi_square.hpp"

namespace {

using namespace facet::kernels;

// Beckmann Lambda for roughness alpha (= sqrt2 sigma): (erf(a) - 1)/2 + exp(-a^2)/(2 a sqrt(pi)),
// a = cot theta / alpha, written here independently in long double (with erfc: erf - 1 cancels).
long double beckmann_lambda(long double theta, long double alpha) {
  const long double a = 1 / (std::tan(theta) * alpha);
  return -std::erfc(a) / 2 + std::exp(-a * a) / (2 * a * std::sqrt(std::numbers::pi_v<long double>));
}

TEST(GaussianMasking, LambdaMatchesCentredBeckmann) {
  double worst64 = 0, worst32 = 0;
  for (double sigma : {0.05, 0.3, 1.0, 3.0})
    for (double theta = 0.01; theta < 1.57; theta += 0.01)
      for (double phi : {0.0, 1.0}) {
        // Anisotropic: the Beckmann alpha of the view azimuth is sqrt2 sigma_o.
        const double vx = sigma * sigma, vy = 2.5 * vx, c = 0.4 * vx;
        const double var_o = vx * std::cos(phi) * std::cos(phi) + vy * std::sin(phi) * std::sin(phi) +
                             2 * c * std::cos(phi) * std::sin(phi);
        const long double ref = beckmann_lambda(theta, std::sqrt(2 * var_o));
        if (ref < 1e-300L) continue;
        worst64 = std::max(
            worst64,
            static_cast<double>(std::abs(f64::gaussian_smith_lambda({0, 0}, {vx, vy, c}, theta, phi) / ref - 1)));
        if (ref > 1e-30L) {
          const long double ref_f = beckmann_lambda(float(theta), std::sqrt(2 * var_o));
          worst32 = std::max(
              worst32, static_cast<double>(std::abs(f32::gaussian_smith_lambda({0, 0}, {float(vx), float(vy), float(c)},
                                                                               float(theta), float(phi)) /
                                                        ref_f -
                                                    1)));
        }
      }
  std::printf("Lambda vs Beckmann: worst relative f64 %.2g f32 %.2g\n", worst64, worst32);
  EXPECT_LT(worst64, 1e-12);  // Lambda ~ exp(-a^2): relative sensitivity a^2 eps to the rounded inputs
  EXPECT_LT(worst32, 2e-3);   // same, with eps_f and a^2 up to ~ 80 (Lambda > 1e-30)
}

// N = w0 (1 + Lambda): the visible projected area is the projected area of the mean plane w0 divided by G1.
TEST(GaussianMasking, ConsistentWithVisibleSlopeNormalisation) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> uni(0, 1);
  for (int i = 0; i < 200; ++i) {
    const glm::dvec2 mean(uni(rng) - 0.5, uni(rng) - 0.5);
    const glm::dvec3 cov(0.01 + uni(rng), 0.01 + uni(rng), 0.0);
    const double theta = 1.5 * uni(rng), phi = 6 * uni(rng);
    const double w0 = std::cos(theta) - std::sin(theta) * (mean.x * std::cos(phi) + mean.y * std::sin(phi));
    if (w0 <= 0) continue;
    const double N = f64::visible_slope(mean, cov, theta, phi).N;
    const double lambda = f64::gaussian_smith_lambda(mean, cov, theta, phi);
    EXPECT_NEAR(N, w0 * (1 + lambda), 1e-13 * N);
    EXPECT_NEAR(f64::gaussian_smith_g1(mean, cov, theta, phi), w0 / N, 1e-13);
  }
}

TEST(GaussianMasking, HeightCorrelatedShadowingMasking) {
  const glm::dvec2 mean(0.2, -0.1);
  const glm::dvec3 cov(0.3, 0.2, 0.05);
  const double li = f64::gaussian_smith_lambda(mean, cov, 0.9, 0.3),
               lo = f64::gaussian_smith_lambda(mean, cov, 1.2, 2.0);
  EXPECT_NEAR(f64::gaussian_smith_g2(mean, cov, 0.9, 0.3, 1.2, 2.0), 1 / (1 + li + lo), 1e-15);
  // Height correlation: between the uncorrelated product G1 G1 and min(G1, G1); equal to G1 when one
  // side sees everything (theta = 0, Lambda = 0).
  const double g1_i = f64::gaussian_smith_g1(mean, cov, 0.9, 0.3), g1_o = f64::gaussian_smith_g1(mean, cov, 1.2, 2.0);
  EXPECT_GE(f64::gaussian_smith_g2(mean, cov, 0.9, 0.3, 1.2, 2.0), g1_i * g1_o);
  EXPECT_LE(f64::gaussian_smith_g2(mean, cov, 0.9, 0.3, 1.2, 2.0), std::min(g1_i, g1_o));
  EXPECT_NEAR(f64::gaussian_smith_g2(mean, cov, 0.0, 0.0, 1.2, 2.0), f64::gaussian_smith_g1(mean, cov, 1.2, 2.0),
              1e-15);
  // The mean plane faces away from one direction: G2 = 0; Lambda saturates but stays finite.
  EXPECT_EQ(f64::gaussian_smith_g2({5, 0}, cov, 0.9, 0.0, 0.3, 0.0), 0.0);
  EXPECT_TRUE(std::isfinite(f32::gaussian_smith_lambda({5, 0}, {0.3f, 0.2f, 0.05f}, 0.9f, 0.0f)));
  for (float theta : {0.0f, 1e-6f, 0.7f, 1.5707962f})
    for (float mx : {-1e4f, -2.0f, 0.0f, 0.5f, 1e4f}) {
      const float l = f32::gaussian_smith_lambda({mx, 0}, {1e-10f, 1e4f, 0}, theta, 0.0f);
      const float g1 = f32::gaussian_smith_g1({mx, 0}, {1e-10f, 1e4f, 0}, theta, 0.0f);
      EXPECT_TRUE(std::isfinite(l) && l >= 0) << theta << " " << mx;
      EXPECT_TRUE(g1 >= 0 && g1 <= 1) << theta << " " << mx;
    }
}

// Sampling C^(1+Lambda) by inversion: cells of equal probability under the test's own CDF (long double
// std::erfc), chi-square at significance 1e-3 (fixed seed, so deterministic). Equiprobable cells hold
// 2000 expected samples each, so no cell needs pooling.
TEST(GaussianMasking, VisibleHeightSamplingChiSquare) {
  const double h_mean = 0.3, h_sigma = 2.0;
  for (double lambda : {0.0, 0.7, 25.0, 1e6}) {
    auto cdf = [&](long double h) {
      return std::pow(0.5L * std::erfc(-(h - h_mean) / (h_sigma * std::sqrt(2.0L))),
                      1 + static_cast<long double>(lambda));
    };
    const int n = 200000, cells = 100;
    std::vector<double> edges;  // interior edges at CDF = i/cells, found by bisection on the reference CDF
    for (int i = 1; i < cells; ++i) {
      long double lo = -50, hi = 50;
      for (int it = 0; it < 200; ++it) {
        const long double mid = (lo + hi) / 2;
        (cdf(mid) < static_cast<long double>(i) / cells ? lo : hi) = mid;
      }
      edges.push_back(static_cast<double>(lo));
    }
    std::vector<double> count(cells, 0);
    const std::vector<double> expected(cells, double(n) / cells);
    std::mt19937_64 rng(static_cast<unsigned>(lambda * 10) + 5);
    std::uniform_real_distribution<double> uni(0, 1);
    for (int i = 0; i < n; ++i) {
      const double h = f64::visible_height_sample(1 - uni(rng), h_mean, h_sigma, lambda);
      count[std::upper_bound(edges.begin(), edges.end(), h) - edges.begin()] += 1;
    }
    EXPECT_GT(facet::test::chi_square_p_value(count, expected), 1e-3) << "lambda " << lambda;
  }
}

// Inversion round trip, including u near 0 and 1 and huge Lambda (where C -> 1 and only 1 - C matters).
TEST(GaussianMasking, VisibleHeightSampleInvertsTheCdf) {
  for (double lambda : {0.0, 3.0, 1e3, 1e8})
    for (double u : {1e-300, 1e-10, 0.01, 0.3, 0.5, 0.9, 1 - 1e-9}) {
      const double h = f64::visible_height_sample(u, -1.0, 0.5, lambda);
      const double u_back = f64::visible_height_cdf(h, -1.0, 0.5, lambda);
      EXPECT_NEAR(std::log(u_back), std::log(u), 1e-11 * std::max(1.0, std::abs(std::log(u)))) << lambda << " " << u;
      const float hf = f32::visible_height_sample(float(std::max(u, 1e-37)), -1.0f, 0.5f, float(lambda));
      EXPECT_TRUE(std::isfinite(hf));
      if (u > 1e-30 && u < 0.999) {
        EXPECT_NEAR(std::log(f32::visible_height_cdf(hf, -1.0f, 0.5f, float(lambda))), std::log(float(u)),
                    2e-5 * std::max(1.0, std::abs(std::log(u))));
      }
    }
  // pdf integrates the cdf: a central difference agrees.
  const double h = 0.2, dh = 1e-5;
  EXPECT_NEAR(f64::visible_height_pdf(h, 0, 1, 2.5),
              (f64::visible_height_cdf(h + dh, 0, 1, 2.5) - f64::visible_height_cdf(h - dh, 0, 1, 2.5)) / (2 * dh),
              1e-9);
}

// The float Lambda(t) (one Chebyshev series, no loop: docs/masking.md, "Lambda in float") against the closed
// form in long double at the same float t (a = t/sqrt2), relative. Its own error: the fit (1.3e-8), the series'
// rounding (sum |c_k| eps_f < 6e-7 of k(t) (9 + t^2) >= 1) and exp's argument t^2/2 rounded (eps_f t^2/2).
TEST(GaussianMasking, FloatLambdaOfTMatchesTheClosedForm) {
  double worst = 0, worst_t = 0;
  float previous = std::numeric_limits<float>::infinity();
  for (int i = 0; i <= 4000; ++i) {
    const float t = static_cast<float>(1e-4 * std::pow(12.0 / 1e-4, i / 4000.0));
    const long double a = static_cast<long double>(t) / std::numbers::sqrt2_v<long double>;
    const long double ref = (std::exp(-a * a) / (a * std::sqrt(std::numbers::pi_v<long double>)) - std::erfc(a)) / 2;
    const float got = f32::gaussian_smith_lambda_of_t(t);
    const double error = static_cast<double>(std::abs(got / ref - 1));
    const double bound = 1e-6 + 0x1p-24 * double(t) * double(t);
    if (error / bound > worst) {
      worst = error / bound;
      worst_t = t;
    }
    EXPECT_LE(got, previous) << "Lambda rises at t = " << t;  // decreasing in t, as G1 and G2 rely on
    previous = got;
  }
  std::printf("float Lambda(t): worst error / bound %.3g at t = %.6g\n", worst, worst_t);
  EXPECT_LE(worst, 1.0);
}

// Its ends: finite and non-negative on the whole float line, saturated toward t = 0, 0 where phi(t) underflows.
TEST(GaussianMasking, FloatLambdaOfTIsFiniteEverywhere) {
  const float saturated = std::exp(f32::GM_LOG_LAMBDA_MAX);
  for (float t : {0.0f, -1.0f, std::numeric_limits<float>::denorm_min(), 1e-38f, 1e-31f})
    EXPECT_EQ(f32::gaussian_smith_lambda_of_t(t), saturated) << t;
  for (float t : {14.0f, 1e3f, 1e20f, std::numeric_limits<float>::max(), std::numeric_limits<float>::infinity()})
    EXPECT_EQ(f32::gaussian_smith_lambda_of_t(t), 0.0f) << t;
  for (float t = 1e-29f; t < 14.0f; t *= 1.01f) {
    const float l = f32::gaussian_smith_lambda_of_t(t);
    EXPECT_TRUE(std::isfinite(l) && l >= 0.0f) << t;
  }
}

}  // namespace
