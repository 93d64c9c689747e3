// A ray against one bilinear cell of a height field (docs/assets.md §3, eqs. H1-H3), written once for
// the GPU tracer (render/heightfield_trace.glsl, float) and the CPU reference (cpu/heightfield.cpp,
// double). Coordinates are the field's: x, y in texels (cell [x0, x0 + 1] x [y0, y0 + 1]), z along
// the normal; the ray is o + t d with inv_d = 1/d (unused where d = 0).
#ifndef FACET_HEIGHTFIELD_CELL_GLSL
#define FACET_HEIGHTFIELD_CELL_GLSL
#include "lib/prelude.glsl"

// (H1) in the form whose value at u in {0, 1} or v in {0, 1} is exactly the edge's linear blend.
inline real heightfield_bilinear(real4 z, real u, real v) {
  return (real(1) - v) * ((real(1) - u) * z.x + u * z.y) + v * ((real(1) - u) * z.z + u * z.w);
}

// The t where o + t d enters (x) and leaves (y) the slab [a, a + 1] of one axis (d != 0).
inline real2 heightfield_slab(real o, real d, real inv_d, real a) {
  real t_a = (a - o) * inv_d, t_b = (a + real(1) - o) * inv_d;
  return d > real(0) ? real2(t_a, t_b) : real2(t_b, t_a);
}

// Coordinate in [0, 1] of o + t d in the cell [a, a + 1]. Where the ray crosses a face (t equal to
// one end of the slab's interval) the value is snapped to that face, so the two cells sharing a face
// evaluate (H1) at the same point with the same corner heights: f is continuous across cells bit for
// bit, and no ray slips between two cells. With d = 0 the coordinate does not depend on t.
inline real heightfield_cell_coordinate(real o, real d, real t, real a, real2 face_t) {
  if (d == real(0)) return clamp(o - a, real(0), real(1));
  if (t == face_t.x) return d > real(0) ? real(0) : real(1);
  if (t == face_t.y) return d > real(0) ? real(1) : real(0);
  return clamp(o + t * d - a, real(0), real(1));
}

// The first t in [t_lo, t_hi], t > 0, where the ray meets (H1) over the cell with corner heights
// z = (z00, z10, z01, z11) at (x0, y0), or -1. With s = t - t_in, f(s) = z_ray - z_surface =
// A s^2 + B s + C (H3) where A = -e du dv, B = dz - (b + e v0) du - (c + e u0) dv, C = f(t_in),
// b = z10 - z00, c = z01 - z00, e = z00 - z10 - z01 + z11, (du, dv) = (d.x, d.y).
inline real heightfield_cell_hit(real3 o, real3 d, real3 inv_d, real x0, real y0, real4 z, real t_lo, real t_hi) {
  if (d.x == real(0) && !(o.x >= x0 && o.x <= x0 + real(1))) return real(-1);
  if (d.y == real(0) && !(o.y >= y0 && o.y <= y0 + real(1))) return real(-1);
  real2 tx = d.x == real(0) ? real2(t_lo, t_hi) : heightfield_slab(o.x, d.x, inv_d.x, x0);
  real2 ty = d.y == real(0) ? real2(t_lo, t_hi) : heightfield_slab(o.y, d.y, inv_d.y, y0);
  real t_in = max(max(tx.x, ty.x), t_lo), t_out = min(min(tx.y, ty.y), t_hi);
  if (!(t_in <= t_out)) return real(-1);

  real u0 = heightfield_cell_coordinate(o.x, d.x, t_in, x0, tx);
  real v0 = heightfield_cell_coordinate(o.y, d.y, t_in, y0, ty);
  real u1 = heightfield_cell_coordinate(o.x, d.x, t_out, x0, tx);
  real v1 = heightfield_cell_coordinate(o.y, d.y, t_out, y0, ty);
  real f_in = o.z + t_in * d.z - heightfield_bilinear(z, u0, v0);
  real f_out = o.z + t_out * d.z - heightfield_bilinear(z, u1, v1);

  real b = z.y - z.x, c = z.z - z.x, e = z.x - z.y - z.z + z.w;
  real A = -e * d.x * d.y;
  real B = d.z - (b + e * v0) * d.x - (c + e * u0) * d.y;
  real C = f_in;
  real span = t_out - t_in;

  // Real roots of (H3), ascending. Stable form: q = -(B + sign(B) sqrt(disc))/2, roots q/A and C/q.
  bool crossing = (f_in > real(0)) != (f_out > real(0));
  int n_roots = 0;
  real r_lo = real(0), r_hi = real(0);
  if (A == real(0)) {
    if (B != real(0)) {
      r_lo = -C / B;
      n_roots = 1;
    }
  } else {
    real disc = B * B - real(4) * A * C;
    if (disc < real(0) && crossing) disc = real(0);  // a crossing guarantees a root: rounding made disc < 0
    if (disc >= real(0)) {
      real root = sqrt(disc);
      real q = real(-0.5) * (B + (B < real(0) ? -root : root));
      real r1 = q == real(0) ? real(0) : q / A, r2 = q == real(0) ? real(0) : C / q;  // q = 0: B = C = 0, root 0
      r_lo = min(r1, r2);
      r_hi = max(r1, r2);
      n_roots = 2;
    }
  }

  real s = real(-1);
  if (crossing) {
    // Exactly one root lies in [0, span]: take the computed root nearest to that interval and clamp
    // it in (rounding can push it just outside; the signs decide that the crossing exists).
    real lo_distance = max(max(real(0), -r_lo), r_lo - span);
    s = clamp(r_lo, real(0), span);
    if (n_roots == 2 && max(max(real(0), -r_hi), r_hi - span) < lo_distance) s = clamp(r_hi, real(0), span);
    if (n_roots == 0) s = real(-1);
  } else if (n_roots == 2 && r_lo >= real(0) && r_hi <= span) {
    s = r_lo;  // no sign change, yet the ray dips under the surface and out within the cell
  }
  if (s < real(0)) return real(-1);
  real t = t_in + s;
  return t > real(0) ? t : real(-1);  // t = 0: a ray starting on the surface does not hit itself there
}

#endif
