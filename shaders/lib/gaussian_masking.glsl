// Smith masking for a (non-centred, anisotropic) Gaussian slope law N(s_mean, Sigma), the visible
// height distribution under height-correlated masking, and height-correlated shadowing-masking.
// Consistent with visible_slope.glsl: N = w0 (1 + Lambda) with w0 = cos theta - s_mean . omega_xy the
// projected area of the mean plane. Derivation: docs/masking.md.
#ifndef FACET_GAUSSIAN_MASKING_GLSL
#define FACET_GAUSSIAN_MASKING_GLSL
#include "lib/prelude.glsl"
#include "lib/normal_partial_moments.glsl"
#include "lib/slope_view_frame.glsl"
#include "lib/special_functions.glsl"

// Lambda is +inf when the mean plane faces away (t <= 0); it is saturated at exp(GM_LOG_LAMBDA_MAX).
#if REAL_IS_DOUBLE
const real GM_LOG_LAMBDA_MAX = real(690);
const real GM_REAL_TINY = real(1e-300);
#else
const real GM_LOG_LAMBDA_MAX = real(69);
const real GM_REAL_TINY = real(1e-37);
#endif

// Lambda = (N - w0)/w0 = E[max(0, -z)]/t for z ~ N(t, 1), i.e. m_1(-t)/t (for centred slopes this is
// the Beckmann Lambda with a = t/sqrt2). Double: in log form, finite as t -> 0 and t -> inf. Float (the GPU):
// phi(t) k(t)/t, k(t) = 1 - t Q(t)/phi(t), with k(t) (9 + t^2) one Chebyshev series in u = (t - 3)/(t + 3)
// (tools/fit_smith_lambda.py; docs/masking.md, "Lambda in float"): no loop and no log, where the log form's
// continued fraction ran 38 trips for t > 2 (a third of a glossy microsurface's frame, six G2 per pixel).
inline real gaussian_smith_lambda_of_t(real t) {
  if (t <= real(0)) return exp(GM_LOG_LAMBDA_MAX);
#if REAL_IS_DOUBLE
  real log_lambda = normal_partial_moments(-t).log_m1 - log(t);
  return exp(min(log_lambda, GM_LOG_LAMBDA_MAX));
#else
  real u = real(1) - real(6) / (t + real(3));  // finite for t = inf
  real two_u = u + u;
  SfClenshaw s = SfClenshaw(real(0), real(0));
  s = sf_clenshaw_step(s, two_u, real(-2.691006974861064e-08));
  s = sf_clenshaw_step(s, two_u, real(1.9003974053719368e-07));
  s = sf_clenshaw_step(s, two_u, real(7.511542909319155e-07));
  s = sf_clenshaw_step(s, two_u, real(-2.926137623674642e-06));
  s = sf_clenshaw_step(s, two_u, real(-1.730987244060363e-05));
  s = sf_clenshaw_step(s, two_u, real(6.295594398135979e-05));
  s = sf_clenshaw_step(s, two_u, real(0.0003819458370544045));
  s = sf_clenshaw_step(s, two_u, real(-0.002214064581888143));
  s = sf_clenshaw_step(s, two_u, real(-0.0055327400960606165));
  s = sf_clenshaw_step(s, two_u, real(0.1019496842934476));
  s = sf_clenshaw_step(s, two_u, real(-0.543014868855253));
  s = sf_clenshaw_step(s, two_u, real(1.726155069242478));
  s = sf_clenshaw_step(s, two_u, real(-3.4518177514940858));
  real k9 = fma(u, s.b1, real(3.174049103708708) - s.b2);  // k(t) (9 + t^2), within 1.3e-8
  // Saturated below t ~ 4e-31; 0 where phi(t) underflows (t beyond ~13.5) or t^2 overflows
  return min(exp(real(-0.5) * t * t) * FACET_INV_SQRT2PI * k9 / (t * (real(9) + t * t)), exp(GM_LOG_LAMBDA_MAX));
#endif
}

inline real gaussian_smith_lambda(real2 mean, real3 cov, real theta, real phi) {
  return gaussian_smith_lambda_of_t(slope_view_frame(mean, cov, theta, phi).t);
}

// G1 = w0/N = 1/(1 + Lambda); 0 when the mean plane faces away.
inline real gaussian_smith_g1(real2 mean, real3 cov, real theta, real phi) {
  real t = slope_view_frame(mean, cov, theta, phi).t;
  return t > real(0) ? real(1) / (real(1) + gaussian_smith_lambda_of_t(t)) : real(0);
}

// Height-correlated Smith shadowing-masking G2 = 1/(1 + Lambda_i + Lambda_o) (0 if either side faces
// away from the mean plane). Both directions go through one call of each function: a shader compiler
// that inlines every call compiles each call site on its own (docs/render_speed.md, "Pipeline set-up").
inline real gaussian_smith_g2(real2 mean, real3 cov, real theta_i, real phi_i, real theta_o, real phi_o) {
  real denominator = real(1);
  for (int k = 0; k < 2; ++k) {
    real t = slope_view_frame(mean, cov, k == 0 ? theta_i : theta_o, k == 0 ? phi_i : phi_o).t;
    if (t <= real(0)) return real(0);
    denominator += gaussian_smith_lambda_of_t(t);
  }
  return real(1) / denominator;
}

// Visible heights for Gaussian heights N(h_mean, h_sigma^2) with CDF C: the CDF is C(h)^(1 + Lambda),
// evaluated as exp((1 + Lambda) log C) with log C from log Phi (accurate where 1 - C is tiny).
inline real visible_height_cdf(real h, real h_mean, real h_sigma, real lambda) {
  return exp((real(1) + lambda) * sf_log_normal_cdf((h - h_mean) / h_sigma));
}

// Its density (1 + Lambda) C^Lambda c(h).
inline real visible_height_pdf(real h, real h_mean, real h_sigma, real lambda) {
  real z = (h - h_mean) / h_sigma;
  real log_pdf = lambda * sf_log_normal_cdf(z) - real(0.5) * z * z - SF_LOG_SQRT_2PI;
  return (real(1) + lambda) * exp(log_pdf) / h_sigma;
}

// Inverse of the CDF for u in (0, 1]: C = u^(1/(1 + Lambda)), then z = Phi^-1(C) through the upper
// quantile of whichever of C, 1 - C = -expm1(log C) is smaller, so large Lambda (C -> 1) keeps its
// precision.
inline real visible_height_sample(real u, real h_mean, real h_sigma, real lambda) {
  real log_C = log(max(u, GM_REAL_TINY)) / (real(1) + lambda);
  real z = log_C < -SF_LN2 ? -sf_normal_quantile_upper_log(log_C)
                           : sf_normal_quantile_upper_log(log(max(-sf_expm1(log_C), GM_REAL_TINY)));
  return h_mean + h_sigma * z;
}

#endif
