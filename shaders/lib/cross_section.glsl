// One entry point per statistic for the four normal distributions, dispatching on an ndf id:
// 0 Beckmann, 1 GGX (param = isotropic alpha), 2 Kagiwada-Kalaba/ellipsoidal (param = b in (0, 1)),
// 3 spherical Gaussian (param = alpha, kappa = 2/alpha^2). Conventions: docs/cross_sections.md.
#ifndef FACET_CROSS_SECTION_GLSL
#define FACET_CROSS_SECTION_GLSL
#include "lib/prelude.glsl"
#include "lib/ndf_beckmann.glsl"
#include "lib/ndf_ggx.glsl"
#include "lib/ndf_ellipsoidal.glsl"
#include "lib/ndf_spherical_gaussian.glsl"

#define NDF_BECKMANN 0
#define NDF_GGX 1
#define NDF_KK 2
#define NDF_SG 3

// D(m) per steradian.
inline real ndf_D(int ndf, real3 m, real param) {
  if (ndf == NDF_BECKMANN) return ndf_beckmann_D(m, real2(param));
  if (ndf == NDF_GGX) return ndf_ggx_D(m, real2(param));
  if (ndf == NDF_KK) return ndf_kk_D(m, param);
  return ndf_sg_D(m, param);
}

// sigma(w) = integral D(m) max(0, m.w) dm, for any unit w.
inline real ndf_sigma(int ndf, real3 w, real param) {
  if (ndf == NDF_BECKMANN) return ndf_beckmann_sigma(w, real2(param));
  if (ndf == NDF_GGX) return ndf_ggx_sigma(w, real2(param));
  if (ndf == NDF_KK) return ndf_kk_sigma(w, param);
  return ndf_sg_sigma(w, param);
}

inline real ndf_sigma_u(int ndf, real u, real param) {
  return ndf_sigma(ndf, real3(sqrt(max((real(1) - u) * (real(1) + u), real(0))), real(0), u), param);
}

// integral D(m) m_z dm: the slope of the odd part, sigma(w) - sigma(-w) = w_z ndf_mean_z.
inline real ndf_mean_z(int ndf, real param) {
  if (ndf == NDF_KK) return ndf_kk_mean_z(param);
  if (ndf == NDF_SG) return ndf_sg_mean_z(param);
  return real(1);
}

// A sample of the visible normals D(m) max(0, m.wi)/sigma(wi) from two uniforms.
inline real3 ndf_sample_visible(int ndf, real3 wi, real param, real2 u) {
  if (ndf == NDF_BECKMANN) return ndf_beckmann_sample_visible(wi, real2(param), u);
  if (ndf == NDF_GGX) return ndf_ggx_sample_visible(wi, real2(param), u);
  if (ndf == NDF_KK) return ndf_kk_sample_visible(wi, param, u);
  return ndf_sg_sample_visible(wi, param, u);
}

#endif
