// The visible slope distribution D_s of a Gaussian slope law N(s_mean, Sigma) seen from
// omega_o(theta, phi) (Heitz et al. 2014, Filtering Non-Linear Transfer Functions on Surfaces,
// supplemental, eqs. 12-46): its normalisation N (eq. 16) and the mean and covariance of its Gaussian
// approximation, in the surface frame. Instead of the closed form (59)-(69), which cancels
// catastrophically beyond the horizon (docs/errata.md, the visible-slope-* entries), D_s is factored in
// the view frame: z = (cot theta - s_o)/sigma_o has density z phi(z - t)/m_1(t) on z >= 0, and s_perp
// given s_o keeps the Gaussian conditional law of p_s. Derivation: docs/visible_slope.md.
#ifndef FACET_VISIBLE_SLOPE_GLSL
#define FACET_VISIBLE_SLOPE_GLSL
#include "lib/prelude.glsl"
#include "lib/normal_partial_moments.glsl"
#include "lib/slope_view_frame.glsl"

struct VisibleSlope {
  real N;      // eq. (16): projected area of the visible microfacets per unit surface area
  real log_N;  // log N, finite and accurate where N underflows to 0
  real2 mean;  // eqs. (42)-(43)
  real3 cov;   // (var_x, var_y, c_xy), eqs. (44)-(46)
};

// cov = (var_x, var_y, c_xy) of p_s; theta in [0, pi/2), phi any.
inline VisibleSlope visible_slope(real2 mean, real3 cov, real theta, real phi) {
  SlopeViewFrame f = slope_view_frame(mean, cov, theta, phi);
  NormalPartialMoments m = normal_partial_moments(f.t);
  // eq. (16): N = E[max(0, W)] with W = a z, z ~ N(t, 1), i.e. N = a m_1(t).
  real log_N = log(f.a) + m.log_m1;
  // s_o = cot theta - sigma_o z, so E[s_o] - mean_o = -sigma_o (E[z] - t) = -sigma_o/kappa. Beyond the
  // horizon (t < 0) the mean sits near cot theta and is taken from there, without cancellation.
  real delta_o = -f.sigma_o / m.kappa;
  real ds_mean_o = f.t >= real(0) ? f.mean_o + delta_o : f.cos_theta / f.sin_theta - f.sigma_o * m.mean_z;
  real ds_var_o = f.var_o * m.var_z;
  // s_perp | s_o ~ N(mean_perp + beta (s_o - mean_o), var_cond): W depends on s_o only.
  real beta = f.cov_o_perp / f.var_o;
  real var_cond = f.det / f.var_o;
  real ds_mean_perp = f.mean_perp + beta * delta_o;
  real ds_var_perp = var_cond + beta * beta * ds_var_o;
  real ds_cov_o_perp = beta * ds_var_o;
  // Back to the surface frame, eqs. (42)-(46).
  real c = f.cos_phi;
  real s = f.sin_phi;
  real2 ds_mean = real2(ds_mean_o * c - ds_mean_perp * s, ds_mean_o * s + ds_mean_perp * c);
  real var_x = ds_var_o * c * c + ds_var_perp * s * s - real(2) * ds_cov_o_perp * c * s;
  real var_y = ds_var_o * s * s + ds_var_perp * c * c + real(2) * ds_cov_o_perp * c * s;
  real c_xy = (ds_var_o - ds_var_perp) * c * s + ds_cov_o_perp * (c * c - s * s);
  // The exact covariance is PSD (its determinant is var_cond ds_var_o >= 0); keep it so after rounding.
  var_x = max(var_x, real(0));
  var_y = max(var_y, real(0));
  real c_max = sqrt(var_x * var_y);
  return VisibleSlope(exp(log_N), log_N, ds_mean, real3(var_x, var_y, clamp(c_xy, -c_max, c_max)));
}

#endif
