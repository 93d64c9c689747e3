// Partial moments of a unit normal of mean t above zero, m_k(t) = int_0^inf z^k phi(z - t) dz.
// In the view frame the visible slope law of z = (cot theta - s_o)/sigma_o is z phi(z - t)/m_1(t) on
// z >= 0 (docs/errata.md#visible-slope-cancellation), so D_s needs only the ratios below; derivation in docs/visible_slope.md.
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
// cancellation-free; NPM_CF_DEPTH terms converge to 1e-17 (double) / 1e-8 (float) at the threshold.
#if REAL_IS_DOUBLE
const real NPM_CF_THRESHOLD = real(4);
const int NPM_CF_DEPTH = 48;
#else
const real NPM_CF_THRESHOLD = real(2);
const int NPM_CF_DEPTH = 40;
#endif

inline NormalPartialMoments normal_partial_moments(real t) {
  if (t >= -NPM_CF_THRESHOLD) {
    // m_1 = m_0 (t + rho), m_2 = t m_1 + m_0, m_3 = t m_2 + 2 m_1 with rho = phi(t)/Phi(t); the
    // forward recurrence cancels only mildly here (at most ~1e3 eps at t = -4).
    real rho = sf_phi_over_Phi(t);
    real kappa = t + rho;
    real r = real(1) / kappa;
    return NormalPartialMoments(kappa, t + r, real(1) - r * (r - rho), sf_log_normal_cdf(t) + log(kappa));
  }
  real x = -t;
  real p = real(0);
  for (int k = NPM_CF_DEPTH; k >= 3; --k) p = real(k) / (x + p);
  real p3 = p;
  real p2 = real(2) / (x + p3);
  real p1 = real(1) / (x + p2);
  // m_1 = phi(t) (1 - x R(x)) with Mills' ratio R = 1/(x + P_1), i.e. m_1 = phi(t) P_1/(x + P_1).
  real log_m1 = real(-0.5) * x * x - SF_LOG_SQRT_2PI + log(p1 / (x + p1));
  return NormalPartialMoments(p1, p2, p2 * (p3 - p2), log_m1);
}

#endif
