// Beckmann normal distribution (Gaussian slopes, anisotropic roughness alpha = (alpha_x, alpha_y)),
// per steradian and normalised by integral D(m) m_z dm = 1 (d'Eon eqs. 19-22; docs/cross_sections.md).
// Every statistic depends on the horizon variable t = sqrt2 w_z / alpha_w, alpha_w^2 = ax^2 wx^2 + ay^2 wy^2,
// and is taken from the partial moments m_k(t) of normal_partial_moments.glsl, which stay accurate
// however far below the horizon w looks (docs/errata.md#visible-slope-cancellation).
#ifndef FACET_NDF_BECKMANN_GLSL
#define FACET_NDF_BECKMANN_GLSL
#include "lib/prelude.glsl"
#include "lib/special_functions.glsl"
#include "lib/normal_partial_moments.glsl"
#include "lib/gaussian_masking.glsl"

#if REAL_IS_DOUBLE
const int NDF_BECKMANN_NEWTON_STEPS = 60;
const real NDF_BECKMANN_NEWTON_TOL = real(1e-14);
#else
const int NDF_BECKMANN_NEWTON_STEPS = 40;
const real NDF_BECKMANN_NEWTON_TOL = real(1e-6);
#endif
// |t| beyond this is the same as infinity in both precisions (mirror-like or grazing views).
#define NDF_BECKMANN_T_MAX real(1e30)

// D(m) = exp(-(mx^2/ax^2 + my^2/ay^2)/mz^2) / (pi ax ay mz^4) on mz > 0 (eq. 19).
inline real ndf_beckmann_D(real3 m, real2 alpha) {
  if (m.z <= real(0)) return real(0);
  real z2 = m.z * m.z;
  real tan2 = (m.x * m.x / (alpha.x * alpha.x) + m.y * m.y / (alpha.y * alpha.y)) / z2;
  return FACET_INV_PI * exp(-tan2) / (alpha.x * alpha.y * z2 * z2);
}

inline real ndf_beckmann_projected_alpha(real3 w, real2 alpha) {
  return sqrt(alpha.x * alpha.x * w.x * w.x + alpha.y * alpha.y * w.y * w.y);
}

// t = sqrt2 w_z / alpha_w, saturated at +-NDF_BECKMANN_T_MAX (and +T_MAX when alpha_w = 0, w_z = 0).
inline real ndf_beckmann_t(real3 w, real alpha_w) {
  if (alpha_w * NDF_BECKMANN_T_MAX <= abs(w.z)) return w.z < real(0) ? -NDF_BECKMANN_T_MAX : NDF_BECKMANN_T_MAX;
  return FACET_SQRT2 * w.z / alpha_w;
}

// sigma(w) = (alpha_w/sqrt2) m_1(t), m_1(t) = t Phi(t) + phi(t): eq. (22) with a = t/sqrt2.
inline real ndf_beckmann_sigma(real3 w, real2 alpha) {
  real alpha_w = ndf_beckmann_projected_alpha(w, alpha);
  if (alpha_w == real(0)) return max(w.z, real(0));
  return alpha_w * SF_INV_SQRT2 * exp(normal_partial_moments(ndf_beckmann_t(w, alpha_w)).log_m1);
}

// Smith Lambda(w) = sigma/w_z - 1 = m_1(-t)/t for w_z > 0 (+inf-saturated for w_z <= 0).
inline real ndf_beckmann_lambda(real3 w, real2 alpha) {
  return gaussian_smith_lambda_of_t(ndf_beckmann_t(w, ndf_beckmann_projected_alpha(w, alpha)));
}

// Visible slopes. In the stretched view frame the slope along the view, in units of its standard
// deviation, is s = -x, and x has density (x + t) phi(x) / m_1(t) on x > -t (z = x + t is the variable
// of docs/errata.md#visible-slope-cancellation). Its upper tail T(x) = phi(x) + t Q(x) is inverted for T(x) = xi T(-t) by safeguarded
// Newton on log T, with
//   log T = log phi(x) + log((k + x + t)/(x + k)) for x >= 0, k = m_1(-x)/m_0(-x)
//   (so that Q/phi = 1/(x + k) and 1 - x Q/phi = k/(x + k), both without cancellation),
//   T = phi(x) + t Phi(-x) for x < 0 (then t > 0 and both terms are positive),
//   d log T/dx = -(x + t) phi(x)/T.
// The unknown is x for t >= 0 and z = x + t for t < 0, whichever is O(1).
struct NdfBeckmannTail {
  real log_T;
  real dlog_T;
};

inline NdfBeckmannTail ndf_beckmann_tail(real x, real z, real t) {
  if (x >= real(0)) {
    real k = normal_partial_moments(-x).kappa;
    real ratio = (k + z) / (x + k);
    return NdfBeckmannTail(real(-0.5) * x * x - SF_LOG_SQRT_2PI + log(ratio), -z / ratio);
  }
  real pdf = sf_normal_pdf(x);
  real T = pdf + t * sf_normal_cdf(-x);
  return NdfBeckmannTail(log(T), -z * pdf / T);
}

inline real ndf_beckmann_sample_x(real t, real xi) {
  bool solve_z = t < real(0);
  real lo = solve_z ? real(0) : max(-t, real(-13));
  real hi = max(lo, real(0)) + real(13);  // T(hi) < 1e-37 T(lo) for every t
  real lo_x = solve_z ? -t : lo;
  real target = ndf_beckmann_tail(lo_x, lo_x + t, t).log_T + log(max(xi, real(1e-30)));
  real v = solve_z ? real(2) / (real(2) - t) : clamp(real(0), lo, hi);  // near the mean
  for (int i = 0; i < NDF_BECKMANN_NEWTON_STEPS; ++i) {
    real x = solve_z ? v - t : v;
    real z = solve_z ? v : v + t;
    NdfBeckmannTail tail = ndf_beckmann_tail(x, z, t);
    real g = tail.log_T - target;
    if (g > real(0)) lo = v; else hi = v;
    real next = tail.dlog_T < real(0) ? v - g / tail.dlog_T : real(0.5) * (lo + hi);
    if (!(next > lo && next < hi)) next = real(0.5) * (lo + hi);
    bool done = abs(next - v) <= NDF_BECKMANN_NEWTON_TOL * (real(1) + abs(v));
    v = next;
    if (done) break;
  }
  return solve_z ? v - t : v;
}

// Standard normal quantile from the upper-tail quantile of special_functions.glsl.
inline real ndf_beckmann_normal_quantile(real p) {
  return p < real(0.5) ? -sf_normal_quantile_upper_log(log(p)) : sf_normal_quantile_upper_log(log(real(1) - p));
}

// Visible normals D(m) max(0, m.wi)/sigma(wi) for any wi: stretch wi by alpha (unit roughness, slopes
// N(0, 1/2) per axis), sample the slope along the view from ndf_beckmann_sample_x (u.x) and the
// orthogonal slope from its Gaussian (u.y), rotate back and unstretch.
inline real3 ndf_beckmann_sample_visible(real3 wi, real2 alpha, real2 u) {
  real3 v = real3(alpha.x * wi.x, alpha.y * wi.y, wi.z);
  real r = sqrt(v.x * v.x + v.y * v.y);
  real cos_phi = r > real(0) ? v.x / r : real(1);
  real sin_phi = r > real(0) ? v.y / r : real(0);
  real t = ndf_beckmann_t(wi, r);
  real slope_o = -SF_INV_SQRT2 * ndf_beckmann_sample_x(t, u.x);
  real slope_perp = SF_INV_SQRT2 * ndf_beckmann_normal_quantile(u.y);
  real sx = alpha.x * (cos_phi * slope_o - sin_phi * slope_perp);
  real sy = alpha.y * (sin_phi * slope_o + cos_phi * slope_perp);
  // Scaled before normalising: slopes reach 1e30 for views from straight below (where the visible
  // normals tend to horizontal ones), and their squares would overflow.
  real scale = max(max(abs(sx), abs(sy)), real(1));
  return normalize(real3(-sx / scale, -sy / scale, real(1) / scale));
}

#endif
