// Ray-triangle and ray-box intersection for the GPU's BVH traversal.
#ifndef FACET_TRIANGLE_INTERSECT_GLSL
#define FACET_TRIANGLE_INTERSECT_GLSL
#include "lib/prelude.glsl"

// Moller-Trumbore. Returns (t, b1, b2) with t = -1 on a miss; the hit point is
// (1 - b1 - b2) p0 + b1 p1 + b2 p2.
inline real3 intersect_triangle(real3 o, real3 d, real3 p0, real3 p1, real3 p2, real t_min, real t_max) {
  real3 e1 = p1 - p0;
  real3 e2 = p2 - p0;
  real3 pv = cross(d, e2);
  real det = dot(e1, pv);
  if (det == real(0)) return real3(real(-1), real(0), real(0));
  real inv_det = real(1) / det;
  real3 tv = o - p0;
  real b1 = dot(tv, pv) * inv_det;
  if (b1 < real(0) || b1 > real(1)) return real3(real(-1), real(0), real(0));
  real3 qv = cross(tv, e1);
  real b2 = dot(d, qv) * inv_det;
  if (b2 < real(0) || b1 + b2 > real(1)) return real3(real(-1), real(0), real(0));
  real t = dot(e2, qv) * inv_det;
  if (t <= t_min || t >= t_max) return real3(real(-1), real(0), real(0));
  return real3(t, b1, b2);
}

// Slab test; inv_d = 1/d (infinite components are fine). Returns the entry distance, or
// -1 when the box is missed or lies beyond t_max.
inline real intersect_box(real3 o, real3 inv_d, real3 lo, real3 hi, real t_max) {
  real3 t0 = (lo - o) * inv_d;
  real3 t1 = (hi - o) * inv_d;
  real3 t_near = min(t0, t1);
  real3 t_far = max(t0, t1);
  real enter = max(max(t_near.x, t_near.y), max(t_near.z, real(0)));
  real leave = min(min(t_far.x, t_far.y), min(t_far.z, t_max));
  return enter <= leave ? enter : real(-1);
}

#endif
