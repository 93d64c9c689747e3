// The glossy lobe of one facet of a traced microsurface, as the reference shades each sample and the
// GPU shades a traced hit: a Beckmann microfacet BRDF (roughness alpha, Smith height-correlated G2)
// in the facet's own frame (normal n, tangent = the plane's tangent projected onto the facet).
#ifndef FACET_BECKMANN_FACET_GLSL
#define FACET_BECKMANN_FACET_GLSL
#include "lib/prelude.glsl"
#include "lib/ndf_beckmann.glsl"

// The facet's own frame: normal n, tangent the plane's `tangent` projected onto the facet.
struct BeckmannFacetFrame {
  real3 t;
  real3 b;
  real3 n;
};

inline BeckmannFacetFrame beckmann_facet_frame(real3 n, real3 tangent) {
  real3 t = normalize(tangent - dot(tangent, n) * n);
  return BeckmannFacetFrame(t, cross(n, t), n);
}

inline real3 beckmann_facet_local(BeckmannFacetFrame f, real3 w) { return real3(dot(w, f.t), dot(w, f.b), dot(w, f.n)); }

// Smith's height-correlated G2 = 1/(1 + Lambda_i + Lambda_o) of the lobe, wi and wo in the facet's frame;
// both Lambdas through one call (a shader compiler that inlines every call compiles each call site on its
// own: docs/render_speed.md, "Pipeline set-up").
inline real beckmann_facet_g2(real3 wi, real3 wo, real2 alpha) {
  real denominator = real(1);
  for (int k = 0; k < 2; ++k) denominator += ndf_beckmann_lambda(k == 0 ? wi : wo, alpha);
  return real(1) / denominator;
}

// f(v, l) cos(theta_l) = D(h) G2(v, l) / (4 cos(theta_v)) for unit n, v (toward the viewer) and l
// (toward the light) both above the facet; 0 otherwise.
inline real beckmann_facet_specular(real3 n, real3 tangent, real3 v, real3 l, real2 alpha) {
  BeckmannFacetFrame f = beckmann_facet_frame(n, tangent);
  real3 wi = beckmann_facet_local(f, l);
  real3 wo = beckmann_facet_local(f, v);
  if (!(wi.z > real(0) && wo.z > real(0))) return real(0);
  return ndf_beckmann_D(normalize(wi + wo), alpha) * beckmann_facet_g2(wi, wo, alpha) / (real(4) * wo.z);
}

#endif
