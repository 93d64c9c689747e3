// Ray intersection with facet's analytic primitives (shared by the GPU passes and the CPU twin).
// A ray is o + t d with unit d; every function returns the nearest t in (t_min, t_max), or -1.
#ifndef FACET_ANALYTIC_INTERSECT_GLSL
#define FACET_ANALYTIC_INTERSECT_GLSL
#include "lib/prelude.glsl"

inline real intersect_plane(real3 o, real3 d, real3 point, real3 normal, real t_min, real t_max) {
  real denom = dot(d, normal);
  if (abs(denom) < real(1e-12)) return real(-1);  // parallel: no (or a degenerate) hit
  real t = dot(point - o, normal) / denom;
  return (t > t_min && t < t_max) ? t : real(-1);
}

// Stable quadratic: with b' = d.(o - c), the discriminant is evaluated as r^2 - |f - b'd|^2
// where f = o - c (Ray Tracing Gems, ch. 7), which does not cancel for far-away spheres.
inline real intersect_sphere(real3 o, real3 d, real3 center, real radius, real t_min, real t_max) {
  real3 f = o - center;
  real b = dot(f, d);
  real3 h = f - b * d;
  real disc = radius * radius - dot(h, h);
  if (disc < real(0)) return real(-1);
  real q = -b - sign(b) * sqrt(disc);
  if (b == real(0)) q = -sqrt(disc);
  real c = dot(f, f) - radius * radius;
  real t0 = c / q;
  real t1 = q;
  real near_t = min(t0, t1);
  real far_t = max(t0, t1);
  if (near_t > t_min && near_t < t_max) return near_t;
  if (far_t > t_min && far_t < t_max) return far_t;
  return real(-1);
}

#endif
