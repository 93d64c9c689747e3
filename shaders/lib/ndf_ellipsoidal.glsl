// Kagiwada-Kalaba ("ellipsoidal") normal distribution on the whole sphere, parameter b in (0, 1):
// density in u = m_z proportional to 1/(1 - b u) (d'Eon eq. 26); per steradian and normalised by
// integral D(m) dm = 1. b -> 0 is the isotropic distribution, b -> 1 a flat surface (slowly:
// the normaliser L = log((1+b)/(1-b)) grows only logarithmically). docs/cross_sections.md.
#ifndef FACET_NDF_ELLIPSOIDAL_GLSL
#define FACET_NDF_ELLIPSOIDAL_GLSL
#include "lib/prelude.glsl"
#include "lib/special_functions.glsl"
#include "lib/ndf_common.glsl"

// b is clamped to [1e-6, 1 - 1e-6]: the formulas are 0/0 at b = 0 and singular at b = 1, and the
// clamp changes sigma by less than 1e-6 (docs/cross_sections.md).
inline real ndf_kk_clamp_b(real b) { return clamp(b, real(1e-6), real(1) - real(1e-6)); }

// L = log((1+b)/(1-b)) = log1p(b) - log1p(-b), both terms of opposite sign.
inline real ndf_kk_norm(real b) { return sf_log1p(b) - sf_log1p(-b); }

// D(m) = b / (2 pi L (1 - b m_z)) (eq. 26 divided by 2 pi).
inline real ndf_kk_D(real3 m, real b_in) {
  real b = ndf_kk_clamp_b(b_in);
  return real(0.5) * FACET_INV_PI * b / (ndf_kk_norm(b) * (real(1) - b * m.z));
}

// E[m_z] = 1/b - 2/L: the slope of the linear (odd) part of sigma, sigma(u) - sigma(-u) = u E[m_z].
inline real ndf_kk_mean_z(real b_in) {
  real b = ndf_kk_clamp_b(b_in);
  real L = ndf_kk_norm(b);
  // 1/b - 2/L = (L - 2b) / (b L), and L - 2b = (log1p(b) - b) - (log1p(-b) + b) has no cancellation.
  return (ndf_log1p_minus_x(b) - ndf_log1p_minus_x(-b)) / (b * L);
}

// sigma(u), d'Eon's eq. (27) divided by 2 pi (docs/errata.md#cross-section-2pi), rearranged with
// R = sqrt(1 - b^2 (1 - u^2)):
//   L sigma = b (1 - u^2)/(1 + R) + u [ln((1+b)(1-u)/(R-u)) / b - 1].
// For u >= 0, (1-u)/(R-u) = (R+u)/((1+u)(1-b^2)) and the bracket is
//   [log1p(-b^2 (1-u)/(1+R)) - (log1p(-b) + b)] / b;
// for u < 0 it is [(log1p(b) - b) + log1p(b^2 (1-u^2)/((1+R)(R-u)))] / b.
// Every term is computed without cancellation (docs/cross_sections.md).
inline real ndf_kk_sigma_u(real u, real b_in) {
  real b = ndf_kk_clamp_b(b_in);
  real L = ndf_kk_norm(b);
  real s2 = max((real(1) - u) * (real(1) + u), real(0));
  real R = sqrt(real(1) - b * b * s2);
  real bracket;
  if (u >= real(0)) {
    bracket = (sf_log1p(-b * b * (real(1) - u) / (real(1) + R)) - ndf_log1p_minus_x(-b)) / b;
  } else {
    bracket = (ndf_log1p_minus_x(b) + sf_log1p(b * b * s2 / ((real(1) + R) * (R - u)))) / b;
  }
  return max((b * s2 / (real(1) + R) + u * bracket) / L, real(0));
}

inline real ndf_kk_sigma(real3 w, real b) { return ndf_kk_sigma_u(w.z, b); }

// Inverse CDF of the density in u: 1 - b u = (1+b) ((1-b)/(1+b))^xi, i.e.
// u = -expm1(log1p(b) - xi L) / b.
inline real ndf_kk_sample_u(real xi, real b) {
  return clamp(-sf_expm1(sf_log1p(b) - xi * ndf_kk_norm(b)) / b, real(-1), real(1));
}

// Visible normals D(m) max(0, m.wi) / sigma(wi) by rejection: propose m ~ D, accept with
// probability max(0, m.wi). The acceptance rate is sigma(wi) >= sigma(-1) = (b - log1p(b))/(b L),
// at least 0.02 on the clamped b range, so 1024 attempts fail with probability < 1e-9; the
// last proposal is returned then (docs/cross_sections.md).
inline real3 ndf_kk_sample_visible(real3 wi, real b_in, real2 u) {
  real b = ndf_kk_clamp_b(b_in);
  NdfRng rng = ndf_rng_seed(u);
  real2 xi = u;
  real3 m = real3(0, 0, 1);
  for (int attempt = 0; attempt < 1024; ++attempt) {
    real mz = ndf_kk_sample_u(xi.x, b);
    real phi = real(2) * FACET_PI * xi.y;
    real r = sqrt(max(real(1) - mz * mz, real(0)));
    m = real3(r * cos(phi), r * sin(phi), mz);
    rng = ndf_rng_next(rng);
    real accept = ndf_rng_uniform(rng);
    if (accept < dot(m, wi)) break;
    NdfRngPair next = ndf_rng_next_pair(rng);
    rng = next.rng;
    xi = next.xi;
  }
  return m;
}

#endif
