// Exact filtering of a piecewise-linear colour map against a Gaussian N(mu, sigma^2) of the mapped
// scalar (Heitz et al. 2013, "Filtering Color Mapped Textures and Surfaces": E[colormap(t)] over the
// footprint, t ~ N(mu, sigma^2)). A map is the sum of its segments and its two constant end tails; the
// loop over the control points lives with each caller (the C++ reference over a vector), which may evaluate
// each control point's ColormapKnot once and share it between its two segments. The render pass sums
// linear maps by their slopes instead (eq. L1, render/texture_sampling.glsl).
// Derivation, stability argument and tests: docs/colormap_filtering.md.
#ifndef FACET_COLORMAP_FILTER_GLSL
#define FACET_COLORMAP_FILTER_GLSL
#include "lib/prelude.glsl"
#include "lib/special_functions.glsl"

// sigma is clamped to COLORMAP_SIGMA_MIN so that sigma = 0 still gives finite z = (x - mu)/sigma: the
// result is then the point value colormap(mu) up to rounding, except exactly on a step's jump, where
// it is the mean of both sides (the limit sigma -> 0+). |z| is clamped to COLORMAP_Z_MAX (below the
// float range, far above any |x - mu|/sigma of a sensible input) so that no infinity reaches 0 * inf.
const real COLORMAP_SIGMA_MIN = real(1e-30);
const real COLORMAP_Z_MAX = real(1e36);

inline real colormap_standardize(real x, real mu, real sigma) {
  return clamp((x - mu) / max(sigma, COLORMAP_SIGMA_MIN), -COLORMAP_Z_MAX, COLORMAP_Z_MAX);
}

// Phi and G(z) = integral_{-inf}^{z} Phi(u) du = z Phi(z) + phi(z) at z and at -z, from one erfcx and
// one exp. With x = |z| and Mills' ratio R(x) = Q(x)/phi(x) = sqrt(pi/2) erfcx(x/sqrt2):
// Phi(-x) = phi(x) R(x), G(-x) = phi(x) (1 - x R(x)) (never a quotient or difference of underflowing
// numbers; relative error ~x^2 eps, absolute < eps phi(x)), Phi(x) = 1 - Phi(-x), G(x) = x + G(-x).
struct ColormapKnot {
  real Phi;            // Phi(z)
  real Phi_reflected;  // Phi(-z)
  real G;              // G(z)
  real G_reflected;    // G(-z)
};

inline ColormapKnot colormap_knot(real z) {
  real x = abs(z);
  real mills = SF_SQRT_PI_OVER_2 * sf_erfcx_nonneg(x * SF_INV_SQRT2);
  real pdf = sf_normal_pdf(x);
  real Phi_neg = pdf * mills;
  real G_neg = pdf * max(real(1) - x * mills, real(0));
  real Phi_pos = real(1) - Phi_neg;
  real G_pos = x + G_neg;
  return z >= real(0) ? ColormapKnot(Phi_pos, Phi_neg, G_pos, G_neg) : ColormapKnot(Phi_neg, Phi_pos, G_neg, G_pos);
}

// Integral over [x0, x1] of the linear ramp c0 -> c1 against N(mu, sigma^2), from the knots k0 at
// a = (x0 - mu)/sigma and k1 at b = (x1 - mu)/sigma. With s = (c1 - c0)/(b - a) per standard deviation,
// integration by parts gives
//   S = c1 Phi(b) - c0 Phi(a) - s (G(b) - G(a)) = c1 (Phi(b) - Gm) + c0 (Gm - Phi(a)),
//   Gm = (G(b) - G(a))/(b - a), the mean of Phi over [a, b], which lies in [Phi(a), Phi(b)].
// The segment is first reflected (z -> -z, ends swapped) so that its midpoint lies at or left of the
// mean: Phi and G are then taken on their small, accurately known side (no 1 - Phi cancellation in the
// right tail). Gm is clamped to [Phi_lo, Phi_hi], so both colour weights are >= 0.
// A constant segment (c0 = c1, steps) gives c0 (Phi(b) - Phi(a)).
inline real3 colormap_segment_from_knots(ColormapKnot k0, ColormapKnot k1, real a, real b, real3 c0, real3 c1) {
  bool reflect = a + b > real(0);
  real width = b - a;
  real Phi_lo = reflect ? k1.Phi_reflected : k0.Phi;
  real Phi_hi = reflect ? k0.Phi_reflected : k1.Phi;
  real G_lo = reflect ? k1.G_reflected : k0.G;
  real G_hi = reflect ? k0.G_reflected : k1.G;
  real3 c_lo = reflect ? c1 : c0;
  real3 c_hi = reflect ? c0 : c1;
  real mean_Phi = width > real(0) ? clamp((G_hi - G_lo) / width, Phi_lo, Phi_hi) : Phi_lo;
  return c_hi * (Phi_hi - mean_Phi) + c_lo * (mean_Phi - Phi_lo);
}

inline real3 colormap_segment_gaussian(real x0, real x1, real3 c0, real3 c1, real mu, real sigma) {
  real a = colormap_standardize(x0, mu, sigma);
  real b = colormap_standardize(x1, mu, sigma);
  return colormap_segment_from_knots(colormap_knot(a), colormap_knot(b), a, b, c0, c1);
}

// The constant end colours: c_first on (-inf, x_first] and c_last on [x_last, inf).
inline real3 colormap_tail_below_gaussian(real x_first, real3 c_first, real mu, real sigma) {
  return c_first * colormap_knot(colormap_standardize(x_first, mu, sigma)).Phi;
}

inline real3 colormap_tail_above_gaussian(real x_last, real3 c_last, real mu, real sigma) {
  return c_last * colormap_knot(colormap_standardize(x_last, mu, sigma)).Phi_reflected;
}

#endif
