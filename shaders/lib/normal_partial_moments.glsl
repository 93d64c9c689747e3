// Partial moments of a unit normal of mean t above zero, m_k(t) = int_0^inf z^k phi(z - t) dz.
// In the view frame the visible slope law of z = (cot theta - s_o)/sigma_o is z phi(z - t)/m_1(t) on
// z >= 0 (docs/errata.md#visible-slope-cancellation), so D_s needs only the ratios below; derivation in
// docs/visible_slope.md.
#ifndef FACET_NORMAL_PARTIAL_MOMENTS_GLSL
#define FACET_NORMAL_PARTIAL_MOMENTS_GLSL
#include "lib/prelude.glsl"
#include "lib/special_functions.glsl"

struct NormalPartialMoments {
  real kappa;   // m_1/m_0: mean of N(t, 1) truncated to z > 0
  real mean_z;  // m_2/m_1: mean of the z-weighted law z phi(z - t) on z > 0
  real var_z;   // m_3/m_1 - (m_2/m_1)^2: its variance
  real log_m1;  // log m_1, finite where m_1 underflows (t < -38 in double, -13 in float)
};

// Below t = -NPM_CF_THRESHOLD the ratios P_k = m_k/m_{k-1} come from the continued fraction
// P_k = k/(x + P_{k+1}), x = -t (backward recurrence of m_{k+1} = t m_k + k m_{k-1}), which is
// cancellation-free. It is evaluated from k = K = NPM_CF_DEPTH + NPM_CF_DEPTH_X/x down. Above the threshold
// the forward formulas lose accuracy as t falls (var_z: 4e-14 relative at t = -1.25, 2.5e-12 at t = -4 in
// double); below it the fraction needs more terms as x falls (docs/visible_slope.md, "Stable ratios").
// Double: threshold 1.25, K = 208 at x = 1.25, 76 at x = 4, converged to eps; float: 2, K = 40, to 1e-8.
#if REAL_IS_DOUBLE
const real NPM_CF_THRESHOLD = real(1.25);
const int NPM_CF_DEPTH = 16;
const real NPM_CF_DEPTH_X = real(240);
#else
const real NPM_CF_THRESHOLD = real(2);
const int NPM_CF_DEPTH = 40;
const real NPM_CF_DEPTH_X = real(0);
#endif

inline NormalPartialMoments normal_partial_moments(real t) {
  if (t >= -NPM_CF_THRESHOLD) {
    // m_1 = m_0 (t + rho), m_2 = t m_1 + m_0, m_3 = t m_2 + 2 m_1 with rho = phi(t)/Phi(t); the
    // forward recurrence cancels only mildly here (var_z to 4e-14 at t = -1.25 in double).
    // phi/Phi and log Phi share erfcx(|t|/sqrt2) (lib/special_functions.glsl).
    real e = sf_erfcx_nonneg(abs(t) * SF_INV_SQRT2);
    real rho = sf_phi_over_Phi_erfcx(t, e);
    real kappa = t + rho;
    real r = real(1) / kappa;
    return NormalPartialMoments(kappa, t + r, real(1) - r * (r - rho), sf_log_normal_cdf_erfcx(t, e) + log(kappa));
  }
  real x = -t;
  int depth = NPM_CF_DEPTH + int(NPM_CF_DEPTH_X / x);
#if REAL_IS_DOUBLE
  // Start from the fixed point of P = (K + 1)/(x + P), (sqrt(x^2 + 4(K + 1)) - x)/2 written without
  // cancellation (the tail P_k ~ sqrt(k) for k >> x^2): ~40% fewer terms than starting from 0.
  real k1 = real(depth + 1);
  real p = real(2) * k1 / (x + sqrt(x * x + real(4) * k1));
#else
  real p = real(0);  // float keeps its start, so GPU results are unchanged
#endif
  for (int k = depth; k >= 3; --k) p = real(k) / (x + p);
  real p3 = p;
  real p2 = real(2) / (x + p3);
  real p1 = real(1) / (x + p2);
  // m_1 = phi(t) (1 - x R(x)) with Mills' ratio R = 1/(x + P_1), i.e. m_1 = phi(t) P_1/(x + P_1).
  real log_m1 = real(-0.5) * x * x - SF_LOG_SQRT_2PI + log(p1 / (x + p1));
  return NormalPartialMoments(p1, p2, p2 * (p3 - p2), log_m1);
}

#endif
