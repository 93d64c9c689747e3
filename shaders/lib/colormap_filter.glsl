// Exact filtering of a piecewise-linear colour map against a Gaussian N(mu, sigma^2) of the mapped
// scalar (Heitz et al. 2013, "Filtering Color Mapped Textures and Surfaces": E[colormap(t)] over the
// footprint, t ~ N(mu, sigma^2)). A map is the sum of its segments and its two constant end tails; the
// loop over the control points lives with each caller (GLSL over a buffer, C++ over a vector).
// Derivation, stability argument and tests: docs/colormap_filtering.md.
#ifndef FACET_COLORMAP_FILTER_GLSL
#define FACET_COLORMAP_FILTER_GLSL
#include "lib/prelude.glsl"
#include "lib/special_functions.glsl"

// sigma is clamped to this so that (x - mu)/sigma stays finite (or a signed infinity the special
// functions saturate) at sigma = 0; the result then is the point value colormap(mu) up to rounding,
// except exactly on a step's jump, where it is the mean of both sides (the limit sigma -> 0+).
const real COLORMAP_SIGMA_MIN = real(1e-30);

// G(z) = integral_{-inf}^{z} Phi(u) du = z Phi(z) + phi(z) >= 0. For z < 0 it is written as
// phi(z) (1 - |z| R(|z|)) with Mills' ratio R(x) = Q(x)/phi(x) = sqrt(pi/2) erfcx(x/sqrt2), so it never
// subtracts two underflowing numbers; the relative error there grows like z^2 eps, the absolute one
// stays below eps phi(z).
inline real colormap_integrated_cdf(real z) {
  if (z >= real(0)) return z * sf_normal_cdf(z) + sf_normal_pdf(z);
  real mills = SF_SQRT_PI_OVER_2 * sf_erfcx_nonneg(-z * SF_INV_SQRT2);
  return sf_normal_pdf(z) * max(real(1) + z * mills, real(0));
}

// Integral over [x0, x1] of the linear ramp c0 -> c1 against N(mu, sigma^2). With a = (x0 - mu)/sigma,
// b = (x1 - mu)/sigma and the slope s = (c1 - c0)/(b - a) per standard deviation, integration by parts
// gives
//   S = c1 Phi(b) - c0 Phi(a) - s (G(b) - G(a)).
// The segment is first reflected (z -> -z, swapping the ends) so that its midpoint lies at or left of
// the mean: Phi(a), Phi(b) are then the small, accurately known side (no 1 - Phi cancellation in the
// right tail) and G keeps relative accuracy. A constant segment (c0 = c1, steps) gives c0 (Phi(b) - Phi(a)).
inline real3 colormap_segment_gaussian(real x0, real x1, real3 c0, real3 c1, real mu, real sigma) {
  real sd = max(sigma, COLORMAP_SIGMA_MIN);
  real a = (x0 - mu) / sd;
  real b = (x1 - mu) / sd;
  bool reflect = a + b > real(0);
  real lo = reflect ? -b : a;
  real hi = reflect ? -a : b;
  real3 c_lo = reflect ? c1 : c0;
  real3 c_hi = reflect ? c0 : c1;
  real Phi_lo = sf_normal_cdf(lo);
  real Phi_hi = sf_normal_cdf(hi);
  // s (G(hi) - G(lo)) = (c_hi - c_lo) mean_Phi, mean_Phi = (G(hi) - G(lo))/(hi - lo) the mean of Phi over
  // [lo, hi], which lies in [Phi_lo, Phi_hi]: clamped there, both colour weights below are >= 0.
  real width = hi - lo;
  real mean_Phi = width > real(0) ? (colormap_integrated_cdf(hi) - colormap_integrated_cdf(lo)) / width
                                  : Phi_lo;
  mean_Phi = clamp(mean_Phi, Phi_lo, Phi_hi);
  return c_hi * (Phi_hi - mean_Phi) + c_lo * (mean_Phi - Phi_lo);
}

// The constant end colours: c_first on (-inf, x_first] and c_last on [x_last, inf).
inline real3 colormap_tail_below_gaussian(real x_first, real3 c_first, real mu, real sigma) {
  return c_first * sf_normal_cdf((x_first - mu) / max(sigma, COLORMAP_SIGMA_MIN));
}

inline real3 colormap_tail_above_gaussian(real x_last, real3 c_last, real mu, real sigma) {
  return c_last * sf_normal_tail((x_last - mu) / max(sigma, COLORMAP_SIGMA_MIN));
}

#endif
