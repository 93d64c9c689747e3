// Spherical Gaussian (von Mises-Fisher) normal distribution with roughness alpha, kappa = 2/alpha^2
// (d'Eon, The anisotropic cross-section for the spherical Gaussian medium, eq. 28 as corrected in
// docs/errata.md#spherical-gaussian-overflow), per steradian, normalised by integral D(m) dm = 1.
// Its cross-section has no closed form: ndf_sg_sigma is the fast evaluation (measured worst absolute
// error in docs/cross_sections.md); the exact one is CPU-only (renderer/kernels/cross_section_exact).
#ifndef FACET_NDF_SPHERICAL_GAUSSIAN_GLSL
#define FACET_NDF_SPHERICAL_GAUSSIAN_GLSL
#include "lib/prelude.glsl"
#include "lib/special_functions.glsl"
#include "lib/ndf_common.glsl"

// Below this alpha (kappa > 200) the fast sigma uses the cumulant expansion, above it the Legendre
// series; both are within 2e-5 of the exact sigma at the switch (docs/cross_sections.md).
#define NDF_SG_KAPPA_SWITCH real(200)
#define NDF_SG_LEGENDRE_DEGREE 40

inline real ndf_sg_kappa(real alpha) { return real(2) / (alpha * alpha); }

// D(m) = kappa exp(kappa (m_z - 1)) / (2 pi (1 - exp(-2 kappa))): never overflows (docs/errata.md#spherical-gaussian-overflow).
inline real ndf_sg_D(real3 m, real alpha) {
  real kappa = ndf_sg_kappa(alpha);
  return real(0.5) * FACET_INV_PI * kappa * exp(kappa * (m.z - real(1))) / -sf_expm1(real(-2) * kappa);
}

// E[m_z] = coth(kappa) - 1/kappa (Langevin function; eq. 35 is u E[m_z]/2), by its Taylor series
// kappa/3 - kappa^3/45 + 2 kappa^5/945 - kappa^7/4725 + 2 kappa^9/93555 where the direct form cancels.
inline real ndf_sg_mean_z(real alpha) {
  real kappa = ndf_sg_kappa(alpha);
#if REAL_IS_DOUBLE
  const real series_below = real(0.1);
#else
  const real series_below = real(0.5);
#endif
  if (kappa < series_below) {
    real k2 = kappa * kappa;
    return kappa * (real(1) / real(3) +
                    k2 * (real(-1) / real(45) + k2 * (real(2) / real(945) + k2 * (real(-1) / real(4725) + k2 * real(2) / real(93555)))));
  }
  return real(1) / tanh(kappa) - real(1) / kappa;
}

// Legendre (spherical-harmonic) series, d'Eon eq. (38) per steradian:
//   sigma(u) = sum_l (2l+1)/2 c_l h_l P_l(u),  c_l = E[P_l(m_z)] = I_{l+1/2}(kappa)/I_{1/2}(kappa),
//   h_l = int_0^1 x P_l(x) dx = 1/2, 1/3 (l = 0, 1), 0 (odd l > 1), h_2 = 1/8,
//   h_{l+2}/h_l = -(l-1)/(l+4) (even l >= 2).
// Bessel ratios r_l = I_{l+1/2}/I_{l-1/2} = 1/((2l+1)/kappa + r_{l+1}) by backward recurrence (stable),
// started 40 orders above the last term (converged for kappa <= 200).
inline real ndf_sg_sigma_legendre(real u, real kappa) {
  real r[NDF_SG_LEGENDRE_DEGREE + 1];
  real next = real(0);
  for (int l = NDF_SG_LEGENDRE_DEGREE + 40; l >= 1; --l) {
    next = real(1) / (real(2 * l + 1) / kappa + next);
    if (l <= NDF_SG_LEGENDRE_DEGREE) r[l] = next;
  }
  real sum = real(0.25) + real(0.5) * r[1] * u;  // l = 0 and l = 1 (c_1 = r_1 = E[m_z])
  real p_prev = real(1);                         // P_{l-1}
  real p = u;                                    // P_l
  real c = r[1];                                 // c_l
  real h = real(0.125);                          // h_l for the next even l
  for (int l = 2; l <= NDF_SG_LEGENDRE_DEGREE; ++l) {
    real p_next = (real(2 * l - 1) * u * p - real(l - 1) * p_prev) / real(l);
    p_prev = p;
    p = p_next;
    c *= r[l];
    if (l % 2 == 0) {
      sum += real(0.5) * real(2 * l + 1) * c * h * p;
      h *= -real(l - 1) / real(l + 4);
    }
  }
  return max(sum, real(0));  // rounding can leave -1e-8 where sigma underflows (u = -1, kappa = 200)
}

// Cumulant expansion for kappa > 200: t = m.w has mean mu, variance v and third cumulant k3, and
// sigma = E[max(0, t)] = mu Phi(mu/s) + s phi(mu/s) + k3/(6 v) a phi(a), a = -mu/s, s = sqrt(v)
// (Gaussian plus first Edgeworth term). With 1 - m_z ~ Exp(kappa) (exact up to exp(-2 kappa)):
//   mu = u (1 - 1/kappa), v = u^2/kappa^2 + (1-u^2)(1/kappa - 1/kappa^2),
//   k3 = -2 u^3/kappa^3 - 3 u (1-u^2)(1/kappa^2 - 2/kappa^3).
inline real ndf_sg_sigma_cumulant(real u, real kappa) {
  real s2 = max((real(1) - u) * (real(1) + u), real(0));
  real ik = real(1) / kappa;
  real mu = u * (real(1) - ik);
  real v = u * u * ik * ik + s2 * ik * (real(1) - ik);
  real k3 = real(-2) * u * u * u * ik * ik * ik - real(3) * u * s2 * ik * ik * (real(1) - real(2) * ik);
  real s = sqrt(v);
  real b = mu / s;
  real pdf = sf_normal_pdf(b);
  return max(mu * sf_normal_cdf(b) + s * pdf - k3 / (real(6) * v) * b * pdf, real(0));
}

inline real ndf_sg_sigma_u(real u, real alpha) {
  real kappa = ndf_sg_kappa(alpha);
  return kappa > NDF_SG_KAPPA_SWITCH ? ndf_sg_sigma_cumulant(u, kappa) : ndf_sg_sigma_legendre(u, kappa);
}

inline real ndf_sg_sigma(real3 w, real alpha) { return ndf_sg_sigma_u(w.z, alpha); }

// m_z of a vMF sample: 1 + log(xi + (1 - xi) exp(-2 kappa))/kappa, written with log1p/expm1 so that
// it stays accurate as kappa -> 0 (where it tends to 2 xi - 1).
inline real ndf_sg_sample_z(real xi, real kappa) {
  return clamp(real(1) + sf_log1p((real(1) - xi) * sf_expm1(real(-2) * kappa)) / kappa, real(-1), real(1));
}

// Concentrated case (kappa > NDF_SG_KAPPA_SWITCH). The Lambert equal-area map q -> m,
// m_z = 1 - |q|^2/2, m_xy = q sqrt(1 - |q|^2/4), has unit Jacobian, so m ~ vMF exactly when
// q ~ N(0, I/kappa) (truncated to |q| <= 2, a mass of exp(-2 kappa)). In the frame where wi = (s, 0, u),
// m.wi = u m_z + s q_x sqrt(1 - |q|^2/4) <= g(q) = max(u, 0) + s |q_x| + max(-u, 0) |q|^2/2, and
// N(q) g(q) is a mixture of N(q), N(q)|q_x| and N(q)|q|^2/2 with masses max(u,0), s sqrt(2/(pi kappa)),
// max(-u,0)/kappa. Rejection from it accepts with rate sigma / (sum of masses): >= 1/2 for u >= 0 and
// every kappa > 200; for u < 0 it falls with sigma (e.g. 4% at u = -alpha).
inline real3 ndf_sg_sample_visible_concentrated(real3 wi, real kappa, real2 u) {
  real s = sqrt(max(wi.x * wi.x + wi.y * wi.y, real(0)));
  real cos_phi = s > real(0) ? wi.x / s : real(1);
  real sin_phi = s > real(0) ? wi.y / s : real(0);
  real sd = inversesqrt(kappa);
  real mass_const = max(wi.z, real(0));
  real mass_abs = s * sd * SF_SQRT_2_OVER_PI;
  real mass_r2 = max(-wi.z, real(0)) / kappa;
  real mass = mass_const + mass_abs + mass_r2;
  NdfRng rng = ndf_rng_seed(u);
  real3 m = real3(0, 0, 1);
  for (int attempt = 0; attempt < 1024; ++attempt) {
    real xi[5];
    for (int k = 0; k < 5; ++k) {
      rng = ndf_rng_next(rng);
      xi[k] = ndf_rng_uniform(rng);
    }
    real pick = xi[0] * mass;
    real2 q;
    real radial = sqrt(real(-2) * log(real(1) - xi[1]));  // Rayleigh: |N(0, I)| in 2D
    real angle = real(2) * FACET_PI * xi[2];
    if (pick < mass_const) {
      q = sd * radial * real2(cos(angle), sin(angle));
    } else if (pick < mass_const + mass_abs) {
      // density |x| phi(x) for q_x (a signed Rayleigh), Gaussian q_y
      real qx = sd * sqrt(real(-2) * log(real(1) - xi[3])) * (xi[4] < real(0.5) ? real(-1) : real(1));
      q = real2(qx, sd * radial * cos(angle));
    } else {
      // density r^2 N(q): r^2 ~ Gamma(2, kappa/2)
      real r2 = real(-2) / kappa * (log(real(1) - xi[1]) + log(real(1) - xi[3]));
      q = sqrt(r2) * real2(cos(angle), sin(angle));
    }
    real r2 = dot(q, q);
    if (r2 > real(4)) continue;
    real scale = sqrt(real(1) - real(0.25) * r2);
    real mz = real(1) - real(0.5) * r2;
    real visible = wi.z * mz + s * q.x * scale;
    real envelope = max(wi.z, real(0)) + s * abs(q.x) + max(-wi.z, real(0)) * real(0.5) * r2;
    m = real3(scale * (cos_phi * q.x - sin_phi * q.y), scale * (sin_phi * q.x + cos_phi * q.y), mz);
    rng = ndf_rng_next(rng);
    if (ndf_rng_uniform(rng) * envelope < visible) break;
  }
  return m;
}

// Visible normals D(m) max(0, m.wi)/sigma(wi) by rejection. Above NDF_SG_KAPPA_SWITCH see
// ndf_sg_sample_visible_concentrated. For 2 < kappa <= 200 propose m ~ D and accept
// with probability max(0, m.wi) (acceptance rate sigma(wi)); otherwise propose m = normalize(c + wi),
// c uniform on the sphere (density max(0, m.wi)/pi), and accept with D(m)/D_max = exp(kappa (m_z - 1))
// (acceptance 2 sigma (1 - exp(-2 kappa))/kappa). For u >= 0 the rate is >= sigma(0) > 0.028; below
// the horizon it falls with sigma, and after 1024 rejections the last proposal is returned
// (docs/cross_sections.md).
inline real3 ndf_sg_sample_visible(real3 wi, real alpha, real2 u) {
  real kappa = ndf_sg_kappa(alpha);
  if (kappa > NDF_SG_KAPPA_SWITCH) return ndf_sg_sample_visible_concentrated(wi, kappa, u);
  bool propose_from_D = kappa > real(2);
  NdfRng rng = ndf_rng_seed(u);
  real2 xi = u;
  real3 m = real3(0, 0, 1);
  for (int attempt = 0; attempt < 1024; ++attempt) {
    real phi = real(2) * FACET_PI * xi.y;
    real z = propose_from_D ? ndf_sg_sample_z(xi.x, kappa) : real(1) - real(2) * xi.x;
    real r = sqrt(max(real(1) - z * z, real(0)));
    real3 c = real3(r * cos(phi), r * sin(phi), z);
    real accept_probability;
    if (propose_from_D) {
      m = c;
      accept_probability = dot(m, wi);
    } else {
      real3 h = c + wi;
      real len2 = dot(h, h);
      m = len2 > real(0) ? h * inversesqrt(len2) : wi;
      accept_probability = exp(kappa * (m.z - real(1)));
    }
    rng = ndf_rng_next(rng);
    if (ndf_rng_uniform(rng) < accept_probability) break;
    NdfRngPair next = ndf_rng_next_pair(rng);
    rng = next.rng;
    xi = next.xi;
  }
  return m;
}

#endif
