// Special functions for the Gaussian microsurface statistics (GLSL has no erf, erfc, expm1, log1p).
// Every function keeps its *relative* accuracy in the far tails (docs/errata.md#tail-accurate-erf); measured accuracy and
// derivations: docs/visible_slope.md, tests: tests/kernels/special_functions_test.cpp.
#ifndef FACET_SPECIAL_FUNCTIONS_GLSL
#define FACET_SPECIAL_FUNCTIONS_GLSL
#include "lib/prelude.glsl"

#define SF_LOG_SQRT_2PI real(0.91893853320467274178)
#define SF_SQRT_2_OVER_PI real(0.79788456080286535588)
#define SF_SQRT_PI_OVER_2 real(1.2533141373155002512)
#define SF_INV_SQRT2 real(0.70710678118654752440)
#define SF_2_OVER_SQRT_PI real(1.1283791670955125739)
#define SF_LN2 real(0.69314718055994530942)
// Precision-dependent constants: global consts, so each C++ pass (f32, f64) gets its own.
#if REAL_IS_DOUBLE
const real SF_LOG_REAL_MAX = real(709.0);
const int SF_ERF_SERIES_TERMS = 13;
const int SF_EXPM1_SERIES_TERMS = 17;
const int SF_LOG1P_SERIES_TERMS = 18;
const int SF_QUANTILE_NEWTON_STEPS = 3;
#else
const real SF_LOG_REAL_MAX = real(88.0);
const int SF_ERF_SERIES_TERMS = 8;
const int SF_EXPM1_SERIES_TERMS = 9;
const int SF_LOG1P_SERIES_TERMS = 8;
const int SF_QUANTILE_NEWTON_STEPS = 1;
#endif

// exp(-x^2) with the rounding error of x^2 compensated (fma gives x^2 = x2 + err exactly), so the
// relative error stays O(eps) instead of O(x^2 eps) deep in the Gaussian tail.
inline real sf_exp_neg_square(real x) {
  real ax = min(abs(x), real(1e5));  // exp(-1e10) is 0 in every precision; avoids x^2 = inf
  real x2 = ax * ax;
  real err = fma(ax, ax, -x2);
  return exp(-x2) * (real(1) - err);
}

struct SfClenshaw {
  real b1;
  real b2;
};

// One step b_k = c_k + 2u b_{k+1} - b_{k+2} of Clenshaw's recurrence for a Chebyshev series.
inline SfClenshaw sf_clenshaw_step(SfClenshaw s, real two_u, real c_k) {
  return SfClenshaw(fma(two_u, s.b1, c_k - s.b2), s.b1);
}

// erfcx(y) = exp(y^2) erfc(y) for y >= 0. With u = (y - 2)/(y + 2) in [-1, 1), (2 + y) erfcx(y) is a
// smooth function of u whose Chebyshev coefficients (computed with 50-digit mpmath, see
// docs/visible_slope.md) fall below 1e-8 after degree 13 and below 1e-17 after degree 29: float
// sums degrees 0..13, double 0..29. One formula for all y, so no branch loses relative accuracy.
inline real sf_erfcx_nonneg(real y) {
  real u = real(1) - real(4) / (y + real(2));  // = (y - 2)/(y + 2), finite for y = inf
  real two_u = u + u;
  SfClenshaw s = SfClenshaw(real(0), real(0));
#if REAL_IS_DOUBLE
  s = sf_clenshaw_step(s, two_u, real(-1.7806690577981220428e-18));
  s = sf_clenshaw_step(s, two_u, real(-3.0649082226309797896e-18));
  s = sf_clenshaw_step(s, two_u, real(1.0099618299695458559e-17));
  s = sf_clenshaw_step(s, two_u, real(7.1833527063629845983e-17));
  s = sf_clenshaw_step(s, two_u, real(1.262466090151285962e-16));
  s = sf_clenshaw_step(s, two_u, real(-4.5565932479092930349e-16));
  s = sf_clenshaw_step(s, two_u, real(-3.1458698763371822794e-15));
  s = sf_clenshaw_step(s, two_u, real(-4.7174527714212647135e-15));
  s = sf_clenshaw_step(s, two_u, real(2.5790085510064651231e-14));
  s = sf_clenshaw_step(s, two_u, real(1.4837451497193234115e-13));
  s = sf_clenshaw_step(s, two_u, real(1.2291200427581261108e-13));
  s = sf_clenshaw_step(s, two_u, real(-1.7172845686503592951e-12));
  s = sf_clenshaw_step(s, two_u, real(-7.1429862976954088901e-12));
  s = sf_clenshaw_step(s, two_u, real(4.1224277109443392612e-12));
  s = sf_clenshaw_step(s, two_u, real(1.2320780210409171084e-10));
  s = sf_clenshaw_step(s, two_u, real(2.8641645424512447414e-10));
#endif
  s = sf_clenshaw_step(s, two_u, real(-1.2694116556725622363e-9));
  s = sf_clenshaw_step(s, two_u, real(-8.3094432620303966084e-9));
  s = sf_clenshaw_step(s, two_u, real(2.5925693704613125072e-9));
  s = sf_clenshaw_step(s, two_u, real(1.6469217654838986866e-7));
  s = sf_clenshaw_step(s, two_u, real(2.8595216362339729834e-7));
  s = sf_clenshaw_step(s, two_u, real(-3.0309331106342963244e-6));
  s = sf_clenshaw_step(s, two_u, real(-1.0884883291010032067e-5));
  s = sf_clenshaw_step(s, two_u, real(6.5560631483462741209e-5));
  s = sf_clenshaw_step(s, two_u, real(3.2151659830756159516e-4));
  s = sf_clenshaw_step(s, two_u, real(-2.2256894867052649938e-3));
  s = sf_clenshaw_step(s, two_u, real(-7.3422847916732783318e-3));
  s = sf_clenshaw_step(s, two_u, real(1.301903176575730491e-1));
  s = sf_clenshaw_step(s, two_u, real(-7.1087384254099697461e-1));
  return fma(u, s.b1, real(1.1540674772329393772) - s.b2) / (real(2) + y);
}

// erfcx(x) = exp(x^2) erfc(x) on the whole line; for x < 0 it grows like 2 exp(x^2) and is saturated
// where that would overflow (x < -9.3 in float, x < -26.6 in double).
inline real sf_erfcx(real x) {
  if (x >= real(0)) return sf_erfcx_nonneg(x);
  real ax = min(-x, sqrt(SF_LOG_REAL_MAX - real(1)));
  return real(2) / sf_exp_neg_square(ax) - sf_erfcx_nonneg(ax);
}

inline real sf_erfc(real x) {
  real tail = sf_exp_neg_square(x) * sf_erfcx_nonneg(abs(x));
  return x >= real(0) ? tail : real(2) - tail;
}

// erf(x): Maclaurin series for |x| < 1/2 (keeps relative accuracy near 0, where 1 - erfc cancels),
// 1 - erfc(|x|) elsewhere (no cancellation there: erfc(1/2) = 0.48).
inline real sf_erf(real x) {
  real ax = abs(x);
  if (ax < real(0.5)) {
    real x2 = x * x;
    real term = x;
    real sum = x;
    for (int n = 1; n < SF_ERF_SERIES_TERMS; ++n) {
      term *= -x2 / real(n);
      sum += term / real(2 * n + 1);
    }
    return SF_2_OVER_SQRT_PI * sum;
  }
  real magnitude = real(1) - sf_exp_neg_square(ax) * sf_erfcx_nonneg(ax);
  return x >= real(0) ? magnitude : -magnitude;
}

// exp(x) - 1 without cancellation for small |x| (Taylor series), exp(x) - 1 elsewhere.
inline real sf_expm1(real x) {
  if (abs(x) < real(0.5)) {
    real term = x;
    real sum = x;
    for (int n = 2; n <= SF_EXPM1_SERIES_TERMS; ++n) {
      term *= x / real(n);
      sum += term;
    }
    return sum;
  }
  return exp(x) - real(1);
}

// log(1 + x) for x > -1: for |x| < 1/2, 2 atanh(s) with s = x/(2 + x), |s| <= 1/3 (odd series), which
// keeps relative accuracy where log(1 + x) cancels (GPU log is only absolutely accurate near 1).
inline real sf_log1p(real x) {
  if (abs(x) < real(0.5)) {
    real s = x / (real(2) + x);
    real s2 = s * s;
    real power = s;
    real sum = s;
    for (int k = 1; k < SF_LOG1P_SERIES_TERMS; ++k) {
      power *= s2;
      sum += power / real(2 * k + 1);
    }
    return real(2) * sum;
  }
  return log(real(1) + x);
}

// exp(-t^2/2) with t^2 split exactly as above (t/sqrt2 would add a rounding amplified by t^2).
inline real sf_exp_neg_half_square(real t) {
  real at = min(abs(t), real(1e5));
  real t2 = at * at;
  real err = fma(at, at, -t2);
  return exp(real(-0.5) * t2) * (real(1) - real(0.5) * err);
}

// Standard normal density phi(t), upper tail Q(t) = 1 - Phi(t) and distribution Phi(t).
inline real sf_normal_pdf(real t) {
  return FACET_INV_SQRT2PI * sf_exp_neg_half_square(t);
}

// The functions of t below that end in _erfcx take e = sf_erfcx_nonneg(|t|/sqrt2), which callers
// evaluating several of them at one t share: a shader compiler that inlines every call compiles each
// call site on its own (docs/render_speed.md, "Pipeline set-up").
inline real sf_normal_tail_erfcx(real t, real e) {
  real tail = real(0.5) * e * sf_exp_neg_half_square(t);
  return t >= real(0) ? tail : real(1) - tail;
}

inline real sf_normal_tail(real t) {
  return sf_normal_tail_erfcx(t, sf_erfcx_nonneg(abs(t) * SF_INV_SQRT2));
}

inline real sf_normal_cdf(real t) {
  return sf_normal_tail(-t);
}

// Q(x) = 1 - Phi(x) for x >= 0 to an absolute error below 7.5e-8 (no relative accuracy in the tail),
// given e = exp(-x^2/2), which callers share with phi(x): for sums of probabilities weighted by colours,
// where only the absolute error counts. Abramowitz & Stegun 7.1.26, erfc(y) = (a1 s + ... + a5 s^5)
// exp(-y^2) + err, s = 1/(1 + p y), |err| <= 1.5e-7 for y = x/sqrt2 >= 0: one division and five FMAs
// against the erfcx path's two divisions and fourteen Clenshaw steps. Its error is a smooth function of
// x, so differences of Q (or of x Q) over nearby x do not amplify it.
inline real sf_normal_tail_coarse(real x, real e) {
  real s = real(1) / fma(real(0.3275911) * SF_INV_SQRT2, x, real(1));
  real poly = real(1.061405429);
  poly = fma(poly, s, real(-1.453152027));
  poly = fma(poly, s, real(1.421413741));
  poly = fma(poly, s, real(-0.284496736));
  poly = fma(poly, s, real(0.254829592));
  return real(0.5) * s * poly * e;
}

// log Phi(t), finite for every finite t: for t < 0, Phi(t) = erfcx(-t/sqrt2)/2 exp(-t^2/2) is taken
// in log form (Phi underflows below t = -38 in double, -13 in float); for t >= 0, log1p(-Q(t)).
inline real sf_log_normal_cdf_erfcx(real t, real e) {
  if (t < real(0)) return log(real(0.5) * e) - real(0.5) * t * t;
  return sf_log1p(-sf_normal_tail_erfcx(t, e));
}

inline real sf_log_normal_cdf(real t) {
  return sf_log_normal_cdf_erfcx(t, sf_erfcx_nonneg(abs(t) * SF_INV_SQRT2));
}

// phi(t)/Phi(t) (inverse Mills ratio), never a quotient of two underflowing numbers: for t < 0 it is
// sqrt(2/pi)/erfcx(-t/sqrt2), which grows like |t|; for t >= 0 both factors are well scaled.
inline real sf_phi_over_Phi_erfcx(real t, real e) {
  if (t < real(0)) return SF_SQRT_2_OVER_PI / e;
  return sf_normal_pdf(t) / sf_normal_tail_erfcx(-t, e);  // Phi(t) = Q(-t)
}

inline real sf_phi_over_Phi(real t) {
  return sf_phi_over_Phi_erfcx(t, sf_erfcx_nonneg(abs(t) * SF_INV_SQRT2));
}

// The x >= 0 with log Q(x) = log_q, Q(x) = 1 - Phi(x), for log_q <= log(1/2). Newton's method on
// g(x) = log Q(x) - log_q, g'(x) = -1/R(x) with Mills' ratio R = Q/phi = sqrt(pi/2) erfcx(x/sqrt2).
// g is concave and decreasing, so every Newton iterate after the first lies above the root and they
// decrease monotonically to it (no bracketing needed). x0: Abramowitz & Stegun 26.2.23 in
// t = sqrt(-2 log_q), |error| < 4.5e-4 (kept >= 0, where erfcx_nonneg is defined), so one step
// reaches 7e-8 (float; 3.1e-7 with its rounding) and three 4e-16 (double) instead of five and seven
// steps from x0 = t (special_functions_test).
inline real sf_normal_quantile_upper_log(real log_q) {
  real log_q_c = max(min(log_q, -SF_LN2), real(-1e6));
  real t = sqrt(real(-2) * log_q_c);
  real x = max(t - (real(2.515517) + t * (real(0.802853) + t * real(0.010328))) /
                       (real(1) + t * (real(1.432788) + t * (real(0.189269) + t * real(0.001308)))),
               real(0));
  for (int i = 0; i < SF_QUANTILE_NEWTON_STEPS; ++i) {
    real erfcx_x = sf_erfcx_nonneg(x * SF_INV_SQRT2);
    real log_Q = log(real(0.5) * erfcx_x) - real(0.5) * x * x;
    x = max(x + (log_Q - log_q_c) * SF_SQRT_PI_OVER_2 * erfcx_x, real(0));
  }
  return x;
}

#endif
