// Single scattering from a semi-infinite half-space (z < 0) of one-sided specular microflakes with
// normal distribution D (any ndf of cross_section.glsl). Derivation: docs/microflake_brdf.md:
//   f(wi, wo) = D(h) / (4 (sigma(wi) mu_o + sigma(-wo) mu_i)),  h = normalize(wi + wo),
// and sigma(-wo) = sigma(wo) - mu_o E (E = integral D m_z dm) makes the denominator symmetric:
//   sigma(wi) mu_o + sigma(wo) mu_i - E mu_i mu_o.
// For Beckmann and GGX this is the height-correlated Smith microfacet BRDF.
#ifndef FACET_MICROFLAKE_BRDF_GLSL
#define FACET_MICROFLAKE_BRDF_GLSL
#include "lib/prelude.glsl"
#include "lib/cross_section.glsl"

// The symmetric denominator sigma(wi) mu_o + sigma(wo) mu_i - E mu_i mu_o (wi, wo above the surface).
// Both cross-sections come from one call of ndf_sigma (its four distributions), in a loop whose count the
// compiler cannot fold: lavapipe inlines and compiles each call site on its own, and would unroll a loop of
// two constant trips (a fifth of a microflake scene's pipeline set-up; docs/render_speed.md, "Call sites of
// the microflake and diffraction shading"). Its second trip is for wo above the surface, the only case used.
inline real microflake_brdf_denominator(int ndf, real param, real3 wi, real3 wo) {
  real sigma_i = real(0), sigma_o = real(0);
  for (int k = 0; k < (wo.z > real(0) ? 2 : 1); ++k) {
    real sigma = ndf_sigma(ndf, k == 0 ? wi : wo, param);
    if (k == 0) sigma_i = sigma; else sigma_o = sigma;
  }
  real denominator = sigma_i * wo.z + sigma_o * wi.z - ndf_mean_z(ndf, param) * wi.z * wo.z;
  return max(denominator, real(1e-30));
}

// f(wi, wo) for unit wi, wo pointing away from the surface; 0 unless both are above it.
inline real microflake_brdf(int ndf, real param, real3 wi, real3 wo) {
  if (wi.z <= real(0) || wo.z <= real(0)) return real(0);
  return ndf_D(ndf, normalize(wi + wo), param) / (real(4) * microflake_brdf_denominator(ndf, param, wi, wo));
}

#endif
