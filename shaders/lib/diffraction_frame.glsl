// The grating's frame at a surface point, and the radiance of a diffraction material
// (docs/diffraction.md, "Rendering"). The grating patch lies in the tangent plane with its y axis
// (the ridges of "sinusoid", "rectangular", "fingers") along the surface tangent dp/du and its
// height along the shading normal, so the BRDF of diffraction_brdf.glsl sees wi, wr in that frame.
#ifndef FACET_DIFFRACTION_FRAME_GLSL
#define FACET_DIFFRACTION_FRAME_GLSL
#include "lib/prelude.glsl"
#include "lib/spectral_srgb.glsl"

struct DiffractionDirections {
  real3 wi;  // toward the light, grating frame (x across the ridges, y along, z the normal)
  real3 wr;  // toward the viewer
  bool lit;  // both above the surface: the BRDF is defined
};

// n: unit shading normal facing the viewer; below: n is the surface's own normal turned (the viewer is on the
// side its heights fall toward); dpdu: the surface tangent (any length; a zero or normal-parallel one falls
// back to a fixed perpendicular); l, v: unit directions. From below the frame is (-x, -y, -n) of the upper
// side's (eq. R1 of docs/diffraction.md): the underside is the profile -h, whose pattern is the upper side's
// turned by 180 degrees in (u, v), so the tables of h serve both sides. Turning only n (and x with it) would
// mirror the pattern across the tangent.
inline DiffractionDirections diffraction_directions_seen(real3 n, real3 dpdu, real3 l, real3 v, bool below) {
  real3 t = dpdu - dot(dpdu, n) * n;
  if (!(dot(t, t) > real(1e-12) * max(dot(dpdu, dpdu), real(1e-30)))) {
    real3 axis = abs(n.x) < real(0.9) ? real3(real(1), real(0), real(0)) : real3(real(0), real(1), real(0));
    t = axis - dot(axis, n) * n;
  }
  real3 y = normalize(t);
  real3 x = cross(y, n);
  if (below) y = -y;
  real3 wi = real3(dot(l, x), dot(l, y), dot(l, n));
  real3 wr = real3(dot(v, x), dot(v, y), dot(v, n));
  return DiffractionDirections(wi, wr, wi.z > real(0) && wr.z > real(0));
}

// The same from the surface's own normal n (on the side its heights rise toward), the viewer on either side.
inline DiffractionDirections diffraction_directions(real3 n, real3 dpdu, real3 l, real3 v) {
  bool below = dot(v, n) < real(0);
  return diffraction_directions_seen(below ? -n : n, dpdu, l, v, below);
}

// L = rgb(sum_lambda BRDF(lambda) xyz_weight(lambda)) E cos_i visibility, with `xyz` that sum
// (spectral_integration.hpp normalises the weights so a BRDF of 1 gives Y = 1): the diffracted light
// of a light of RGB irradiance E. Out-of-gamut spectral colours keep their negative components
// (linear data; clamping is the display's business), so averages over pixels stay linear.
inline real3 diffraction_radiance_rgb(real3 rgb, real cos_i, real3 light_irradiance, real visibility) {
  return rgb * light_irradiance * (max(cos_i, real(0)) * visibility);
}
inline real3 diffraction_radiance(real3 xyz, real cos_i, real3 light_irradiance, real visibility) {
  return diffraction_radiance_rgb(spectral_xyz_to_linear_srgb(xyz), cos_i, light_irradiance, visibility);
}

#endif
