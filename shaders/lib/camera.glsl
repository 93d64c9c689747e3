// Pinhole camera: the primary ray through a point of the film.
#ifndef FACET_CAMERA_GLSL
#define FACET_CAMERA_GLSL
#include "lib/prelude.glsl"

// `film` is in pixels: (x, y) from the top-left corner, pixel centres at +0.5.
// `right` and `up` are the camera axes scaled by tan(fov_y / 2) * aspect and tan(fov_y / 2),
// so that the film spans [-1, 1] in both scaled axes. Returns the unit direction.
inline real3 camera_ray_direction(real3 forward, real3 right, real3 up, real2 film, real2 resolution) {
  real2 ndc = real(2) * film / resolution - real2(real(1), real(1));
  return normalize(forward + ndc.x * right - ndc.y * up);
}

#endif
