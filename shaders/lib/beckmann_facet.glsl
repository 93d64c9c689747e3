// The glossy lobe of one facet of a traced microsurface, as the reference shades each sample and the
// GPU shades a traced hit: a Beckmann microfacet BRDF (roughness alpha, Smith height-correlated G2)
// in the facet's own frame (normal n, tangent = the plane's tangent projected onto the facet).
#ifndef FACET_BECKMANN_FACET_GLSL
#define FACET_BECKMANN_FACET_GLSL
#include "lib/prelude.glsl"
#include "lib/ndf_beckmann.glsl"

// f(v, l) cos(theta_l) = D(h) G2(v, l) / (4 cos(theta_v)) for unit n, v (toward the viewer) and l
// (toward the light) both above the facet; 0 otherwise.
inline real beckmann_facet_specular(real3 n, real3 tangent, real3 v, real3 l, real2 alpha) {
  real3 t = normalize(tangent - dot(tangent, n) * n);
  real3 b = cross(n, t);
  real3 wi = real3(dot(l, t), dot(l, b), dot(l, n));
  real3 wo = real3(dot(v, t), dot(v, b), dot(v, n));
  if (!(wi.z > real(0) && wo.z > real(0))) return real(0);
  real3 h = normalize(wi + wo);
  // G2 = 1/(1 + Lambda_i + Lambda_o), both through one call (a shader compiler that inlines every call
  // compiles each call site on its own: docs/render_speed.md, "Pipeline set-up").
  real denominator = real(1);
  for (int k = 0; k < 2; ++k) denominator += ndf_beckmann_lambda(k == 0 ? wi : wo, alpha);
  return ndf_beckmann_D(h, alpha) * (real(1) / denominator) / (real(4) * wo.z);
}

#endif
