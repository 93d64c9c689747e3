// Lambertian reflection under one directional light plus a constant ambient irradiance.
#ifndef FACET_LAMBERT_GLSL
#define FACET_LAMBERT_GLSL
#include "lib/prelude.glsl"

// Outgoing radiance L = albedo/pi * (E_light * max(0, n.l) * visibility + E_ambient),
// with n the unit normal facing the viewer and l the unit direction toward the light.
inline real3 lambert_radiance(real3 albedo, real3 n, real3 l, real3 light_irradiance, real visibility,
                       real3 ambient_irradiance) {
  real cos_theta = max(dot(n, l), real(0));
  return albedo * FACET_INV_PI * (light_irradiance * (cos_theta * visibility) + ambient_irradiance);
}

#endif
