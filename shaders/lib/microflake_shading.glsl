// Radiance from a microflake half-space (lib/microflake_brdf.glsl) lit by one directional light
// plus the constant ambient fill that every facet material gets (albedo/pi x ambient).
#ifndef FACET_MICROFLAKE_SHADING_GLSL
#define FACET_MICROFLAKE_SHADING_GLSL
#include "lib/prelude.glsl"
#include "lib/microflake_brdf.glsl"

// The four distributions of cross_section.glsl are isotropic about the normal, so the BRDF only
// needs the directions in *some* frame with z = n: this one is Duff et al. 2017 (JCGT 6(1)),
// continuous except at n.z = 0 and without the singularity of cross(n, fixed axis).
inline real3 to_normal_frame(real3 n, real3 w) {
  real s = n.z >= real(0) ? real(1) : real(-1);
  real a = real(-1) / (s + n.z);
  real b = n.x * n.y * a;
  real3 t = real3(real(1) + s * n.x * n.x * a, s * b, -s * n.x);
  real3 bt = real3(b, s + n.y * n.y * a, -n.y);
  return real3(dot(w, t), dot(w, bt), dot(w, n));
}

// L = albedo (f E cos_i visibility + ambient / pi) for the BRDF value f and cos_i = n.l.
inline real3 microflake_shade(real3 albedo, real f, real cos_i, real3 light_irradiance, real visibility,
                              real3 ambient_irradiance) {
  return albedo * (light_irradiance * (f * max(cos_i, real(0)) * visibility) + ambient_irradiance * FACET_INV_PI);
}

// L = albedo (f(l, v) E (n.l) visibility + ambient / pi); n unit, facing v; v and l unit, away
// from the surface (toward the viewer and the light).
inline real3 microflake_radiance(int ndf, real param, real3 albedo, real3 n, real3 v, real3 l,
                                 real3 light_irradiance, real visibility, real3 ambient_irradiance) {
  real3 wi = to_normal_frame(n, l);
  real3 wo = to_normal_frame(n, v);
  return microflake_shade(albedo, microflake_brdf(ndf, param, wi, wo), wi.z, light_irradiance, visibility,
                          ambient_irradiance);
}

#endif
