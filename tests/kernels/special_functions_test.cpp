// The special functions of shaders/lib/special_functions.glsl, float and double twins, against
// long-double references (80-bit, ~1e-19 relative: std::erfc/erf/expm1/log1p on long double, and
// erfcx = exp(x^2) erfc(x) below x = 100, its asymptotic series above). Errors are relative,
// measured over dense grids including the far tails the visible slope kernel reaches.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "kernels/shared.hpp"

namespace {

using namespace facet::kernels;

long double erfcx_reference(long double x) {
  if (x < 100) return std::exp(x * x) * std::erfc(x);
  long double sum = 1, term = 1;
  for (int n = 1; n < 30; ++n) {
    term *= -(2 * n - 1) / (2 * x * x);
    sum += term;
  }
  return sum / (x * std::sqrt(std::numbers::pi_v<long double>));
}

double rel(long double value, long double reference) { return static_cast<double>(std::abs(value / reference - 1)); }

// Tolerances: double ~8 eps (Chebyshev sum of 30 terms plus the final division); float 8 eps_f.
constexpr double kTolF64 = 2e-15;
constexpr double kTolF32 = 1e-6;

TEST(SpecialFunctions, ErfcxRelativeAccuracyOnWholeHalfLine) {
  double worst64 = 0, worst32 = 0;
  for (double x = 0; x < 1e6; x = x < 10 ? x + 1e-3 : x * 1.01) {
    worst64 = std::max(worst64, rel(f64::sf_erfcx(x), erfcx_reference(x)));
    const float xf = static_cast<float>(x);
    worst32 = std::max(worst32, rel(f32::sf_erfcx(xf), erfcx_reference(xf)));
  }
  for (double x = -26; x < 0; x += 1e-3) worst64 = std::max(worst64, rel(f64::sf_erfcx(x), erfcx_reference(x)));
  for (float x = -9; x < 0; x += 1e-3f) worst32 = std::max(worst32, rel(f32::sf_erfcx(x), erfcx_reference(x)));
  RecordProperty("worst_f64", std::to_string(worst64));
  RecordProperty("worst_f32", std::to_string(worst32));
  EXPECT_LT(worst64, kTolF64);
  EXPECT_LT(worst32, kTolF32);
}

TEST(SpecialFunctions, ErfcAndErfRelativeAccuracyIntoTheTails) {
  double worst64 = 0, worst32 = 0;
  // Down to the smallest normal number: erfc(26.5) = 1e-307, erfc(9.1) = 1.6e-38 (float).
  for (double x = -6; x < 26.5; x += 1e-3) {
    worst64 = std::max(worst64, rel(f64::sf_erfc(x), std::erfc(static_cast<long double>(x))));
    if (std::abs(x) > 1e-3) worst64 = std::max(worst64, rel(f64::sf_erf(x), std::erf(static_cast<long double>(x))));
    const float xf = static_cast<float>(x);
    if (xf < 9.1f) worst32 = std::max(worst32, rel(f32::sf_erfc(xf), std::erfc(static_cast<long double>(xf))));
    if (std::abs(xf) > 1e-3f) worst32 = std::max(worst32, rel(f32::sf_erf(xf), std::erf(static_cast<long double>(xf))));
  }
  for (double x = 1e-30; x < 1e-3; x *= 1.1) {  // erf near 0 keeps relative accuracy
    worst64 = std::max(worst64, rel(f64::sf_erf(x), std::erf(static_cast<long double>(x))));
    worst32 = std::max(
        worst32, rel(f32::sf_erf(static_cast<float>(x)), std::erf(static_cast<long double>(static_cast<float>(x)))));
  }
  RecordProperty("worst_f64", std::to_string(worst64));
  RecordProperty("worst_f32", std::to_string(worst32));
  EXPECT_LT(worst64, kTolF64);
  EXPECT_LT(worst32, kTolF32);
  EXPECT_EQ(f64::sf_erfc(1e300), 0.0);
  EXPECT_EQ(f32::sf_erfc(-1e30f), 2.0f);
}

TEST(SpecialFunctions, Expm1AndLog1pNearZero) {
  double worst64 = 0, worst32 = 0;
  for (double x = -0.99; x < 3; x += 1e-4) {
    if (std::abs(x) < 1e-12) continue;
    for (double y : {x, x * 1e-9}) {
      worst64 = std::max(worst64, rel(f64::sf_expm1(y), std::expm1(static_cast<long double>(y))));
      worst64 = std::max(worst64, rel(f64::sf_log1p(y), std::log1p(static_cast<long double>(y))));
      const float yf = static_cast<float>(y);
      worst32 = std::max(worst32, rel(f32::sf_expm1(yf), std::expm1(static_cast<long double>(yf))));
      worst32 = std::max(worst32, rel(f32::sf_log1p(yf), std::log1p(static_cast<long double>(yf))));
    }
  }
  RecordProperty("worst_f64", std::to_string(worst64));
  RecordProperty("worst_f32", std::to_string(worst32));
  EXPECT_LT(worst64, kTolF64);
  EXPECT_LT(worst32, kTolF32);
}

TEST(SpecialFunctions, NormalRatiosAndLogCdfStayAccurateWhereTheyUnderflow) {
  double worst64 = 0, worst32 = 0;
  for (double t = -1e4; t < 36; t = t < -50 ? t * 0.99 : t + 1e-3) {
    const long double tl = t;
    const long double Phi = 0.5L * std::erfc(-tl / std::sqrt(2.0L));
    const long double log_Phi = t < 0 ? std::log(0.5L * erfcx_reference(-tl / std::sqrt(2.0L))) - 0.5L * tl * tl
                                      : std::log1p(-0.5L * std::erfc(tl / std::sqrt(2.0L)));
    const long double ratio =
        t < 0 ? std::sqrt(2 / std::numbers::pi_v<long double>) / erfcx_reference(-tl / std::sqrt(2.0L))
              : std::exp(-0.5L * tl * tl) / std::sqrt(2 * std::numbers::pi_v<long double>) / Phi;
    worst64 = std::max(worst64, rel(f64::sf_phi_over_Phi(t), ratio));
    worst64 = std::max(worst64, std::abs(f64::sf_log_normal_cdf(t) - static_cast<double>(log_Phi)) /
                                    std::max(1e-300, std::abs(static_cast<double>(log_Phi))));
    if (t > -1e3 && t < 13) {
      const float tf = static_cast<float>(t);
      const long double tfl = tf;
      const long double ratio_f =
          tf < 0 ? std::sqrt(2 / std::numbers::pi_v<long double>) / erfcx_reference(-tfl / std::sqrt(2.0L))
                 : std::exp(-0.5L * tfl * tfl) / std::sqrt(2 * std::numbers::pi_v<long double>) /
                       (0.5L * std::erfc(-tfl / std::sqrt(2.0L)));
      worst32 = std::max(worst32, rel(f32::sf_phi_over_Phi(tf), ratio_f));
    }
  }
  RecordProperty("worst_f64", std::to_string(worst64));
  RecordProperty("worst_f32", std::to_string(worst32));
  EXPECT_LT(worst64, 1e-14);  // 50 eps: exp(-t^2/2) and log of O(1) factors, t up to 36
  EXPECT_LT(worst32, 5e-6);   // 40 eps_f
}

// The coarse tail (Abramowitz & Stegun 7.1.26) promises an absolute error below 7.5e-8 in exact
// arithmetic; float adds about eight roundings of Q <= 1/2 (2.4e-7): bound 3e-7. Far out it is 0.
TEST(SpecialFunctions, CoarseNormalTailHasASmallAbsoluteError) {
  double worst64 = 0, worst32 = 0;
  for (double x = 0; x < 40; x += 1e-3) {
    const long double Q = 0.5L * std::erfc(static_cast<long double>(x) / std::sqrt(2.0L));
    worst64 =
        std::max(worst64, static_cast<double>(std::abs(f64::sf_normal_tail_coarse(x, std::exp(-0.5 * x * x)) - Q)));
    const float xf = static_cast<float>(x);
    const long double Q_f = 0.5L * std::erfc(static_cast<long double>(xf) / std::sqrt(2.0L));
    worst32 = std::max(worst32,
                       static_cast<double>(std::abs(f32::sf_normal_tail_coarse(xf, std::exp(-0.5f * xf * xf)) - Q_f)));
  }
  std::printf("coarse normal tail, absolute error: double %.2e, float %.2e\n", worst64, worst32);
  EXPECT_LT(worst64, 7.5e-8);
  EXPECT_LT(worst32, 3e-7);
  EXPECT_EQ(f32::sf_normal_tail_coarse(1e30f, 0.0f), 0.0f);
}

TEST(SpecialFunctions, UpperQuantileInvertsTheTail) {
  double worst64 = 0, worst32 = 0;
  for (double log_q = -std::numbers::ln2; log_q > -1e4; log_q *= 1.003) {
    // Residual of log Q at the returned x, converted to an error in x through d log Q/dx = -1/R(x).
    const double x = f64::sf_normal_quantile_upper_log(log_q);
    const long double e = erfcx_reference(x / std::sqrt(2.0L));
    const long double residual =
        (std::log(0.5L * e) - 0.5L * x * x - log_q) * std::sqrt(std::numbers::pi_v<long double> / 2) * e;
    worst64 = std::max(worst64, static_cast<double>(std::abs(residual)) / std::max(1.0, x));
    if (log_q > -80) {
      const float lq = static_cast<float>(log_q);
      const float xf = f32::sf_normal_quantile_upper_log(lq);
      const long double ef = erfcx_reference(xf / std::sqrt(2.0L));
      const long double rf = (std::log(0.5L * ef) - 0.5L * xf * static_cast<long double>(xf) - lq) *
                             std::sqrt(std::numbers::pi_v<long double> / 2) * ef;
      worst32 = std::max(worst32, static_cast<double>(std::abs(rf)) / std::max(1.0f, xf));
    }
  }
  RecordProperty("worst_f64", std::to_string(worst64));
  RecordProperty("worst_f32", std::to_string(worst32));
  EXPECT_LT(worst64, kTolF64);
  EXPECT_LT(worst32, kTolF32);
}

}  // namespace
