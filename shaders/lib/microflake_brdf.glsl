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

// f(wi, wo) for unit wi, wo pointing away from the surface; 0 unless both are above it.
inline real microflake_brdf(int ndf, real param, real3 wi, real3 wo) {
  real mu_i = wi.z;
  real mu_o = wo.z;
  if (mu_i <= real(0) || mu_o <= real(0)) return real(0);
  real3 h = normalize(wi + wo);
  real denominator = ndf_sigma(ndf, wi, param) * mu_o + ndf_sigma(ndf, wo, param) * mu_i -
                     ndf_mean_z(ndf, param) * mu_i * mu_o;
  return ndf_D(ndf, h, param) / (real(4) * max(denominator, real(1e-30)));
}

#endif
