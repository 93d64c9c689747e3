// A Gaussian slope law N(s_mean, Sigma) seen from omega_o(theta, phi), expressed in the view frame
// (o, perp) of Heitz et al. 2014 (Filtering Non-Linear Transfer Functions on Surfaces, supplemental)
// eqs. (2)-(10), plus the horizon variable
// t = (cot theta - s_mean_o)/sigma_o that every visibility statistic depends on.
#ifndef FACET_SLOPE_VIEW_FRAME_GLSL
#define FACET_SLOPE_VIEW_FRAME_GLSL
#include "lib/prelude.glsl"

struct SlopeViewFrame {
  real cos_theta;
  real sin_theta;
  real cos_phi;
  real sin_phi;
  real mean_o;      // eq. (6)
  real mean_perp;   // eq. (7)
  real var_o;       // eq. (8)
  real cov_o_perp;  // eq. (10)
  real det;         // |Sigma| = var_o var_perp - cov_o_perp^2, rotation invariant
  real sigma_o;
  real a;           // sin theta sigma_o, so that W(s) = a z with z = (cot theta - s_o)/sigma_o
  real t;           // (cos theta - mean_o sin theta)/a
};

// cov = (var_x, var_y, c_xy).
inline SlopeViewFrame slope_view_frame(real2 mean, real3 cov, real theta, real phi) {
  real cos_theta = cos(theta);
  real sin_theta = sin(theta);
  real c = cos(phi);
  real s = sin(phi);
  real mean_o = mean.x * c + mean.y * s;
  real mean_perp = -mean.x * s + mean.y * c;
  // |Sigma| by Kahan's difference of products: c_xy^2 = w + e exactly, so a correlation of
  // 1 - 1e-6 keeps a relative accuracy of a few eps instead of eps/(1 - rho^2).
  real w = cov.z * cov.z;
  real e = fma(-cov.z, cov.z, w);
  real det = max(fma(cov.x, cov.y, -w) + e, real(0));
  // sigma_o^2 >= smallest eigenvalue >= |Sigma|/tr(Sigma): the floor only absorbs rounding.
  real var_o = max(cov.x * c * c + cov.y * s * s + real(2) * cov.z * c * s, det / (cov.x + cov.y));
  real cov_o_perp = (cov.y - cov.x) * c * s + cov.z * (c * c - s * s);
  real sigma_o = sqrt(var_o);
  real w0 = cos_theta - mean_o * sin_theta;  // W at the mean slope, eq. (17)
  // At normal incidence t = +inf (D_s = p_s, docs/errata.md#visible-slope-normal-incidence); t is capped at 1e15, where every
  // statistic equals its limit to 1e-15, by keeping a >= 1e-15 w0.
  real a = max(sin_theta * sigma_o, w0 * real(1e-15));
  return SlopeViewFrame(cos_theta, sin_theta, c, s, mean_o, mean_perp, var_o, cov_o_perp, det, sigma_o, a,
                        w0 / a);
}

#endif
