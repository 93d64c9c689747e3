// Pixel footprints in texture space (ray differentials) and the MIP level they select.
#ifndef FACET_TEXTURE_FOOTPRINT_GLSL
#define FACET_TEXTURE_FOOTPRINT_GLSL
#include "lib/prelude.glsl"

// The uv offset of a neighbouring pixel's ray o + t d' on the tangent plane through p with normal
// n, given the surface's uv tangents dp/du and dp/dv at p (least squares on the 2x2 normal
// equations, exact when dp/du and dp/dv span the tangent plane; Igehy 1999 "Tracing ray
// differentials", transfer to the plane and projection onto the parameterisation).
inline real2 uv_differential(real3 o, real3 d_offset, real3 p, real3 n, real3 dpdu, real3 dpdv) {
  real denom = dot(d_offset, n);
  if (abs(denom) < real(1e-12)) return real2(real(0), real(0));  // grazing: caller clamps the level
  real3 dp = o + (dot(p - o, n) / denom) * d_offset - p;
  real a = dot(dpdu, dpdu);
  real b = dot(dpdu, dpdv);
  real c = dot(dpdv, dpdv);
  real det = a * c - b * b;
  if (abs(det) < real(1e-30)) return real2(real(0), real(0));
  real ru = dot(dp, dpdu);
  real rv = dot(dp, dpdv);
  return real2(c * ru - b * rv, a * rv - b * ru) / det;
}

// An anisotropic footprint covered by `taps` isotropic lookups spaced along its major axis, each at the
// MIP level of the footprint's width across it (the minor axis, or the major axis / taps where max_taps
// cannot cover the whole elongation): the classic anisotropic filtering scheme (e.g. the
// EWA-approximating hardware filters). Levels are clamped to the chain.
// The pixel's footprint is the parallelogram J [-1/2, 1/2]^2, J = (duv_dx, duv_dy); its axes here are
// those of the rectangle with the same second moments, J J^T / 12 (J's singular vectors, scaled by its
// singular values): a sheared parallelogram's derivative vectors are both long where it is thin across,
// and a level from them would blur it (docs/colormap_filtering.md, "Principal axes").
struct AnisotropicFootprint {
  real lod;
  real taps;
  real2 major;  // the major axis in uv; tap k of n sits at uv + major ((k + 1/2)/n - 1/2)
  real2 minor;  // the minor axis in uv, perpendicular to the major one in texels
  real width;   // one tap's width in texels, which chose lod
  real2 edge_long, edge_short;  // the parallelogram's own edges in uv (duv_dx, duv_dy), the longer first
};

inline AnisotropicFootprint anisotropic_footprint(real2 duv_dx, real2 duv_dy, real2 size, real levels, real max_taps) {
  real2 a = duv_dx * size, b = duv_dy * size;  // in level-0 texels
  // J J^T = [[p, q], [q, r]]: its larger eigenvalue s1^2 and eigenvector e1, each from the better
  // conditioned of the two rows; s2 = |det J| / s1 (no cancellation for thin footprints).
  real p = a.x * a.x + b.x * b.x, q = a.x * a.y + b.x * b.y, r = a.y * a.y + b.y * b.y;
  real half_difference = real(0.5) * (p - r);
  real root = sqrt(half_difference * half_difference + q * q);
  real major = sqrt(real(0.5) * (p + r) + root);
  real minor = major > real(0) ? abs(a.x * b.y - a.y * b.x) / major : real(0);
  real2 e1 = half_difference >= real(0) ? real2(half_difference + root, q) : real2(q, root - half_difference);
  e1 = root > real(0) ? normalize(e1) : real2(real(1), real(0));
  // Within one texel a single bilinear lookup is exact: no taps to spread.
  real taps = major <= real(1) ? real(1) : clamp(ceil(major / max(minor, real(1e-6))), real(1), max_taps);
  real width = max(minor, major / taps);
  // Bilinear lookups at level l spread each level texel over a tent two level texels wide, so the
  // level matching a footprint of `width` texels is about log2(width) - 1. The bias was measured:
  // on scenes/colormap_noise_plane.json (320x180 vs a 16x16 reference) biases 0.5 / 1 / 1.5 gave
  // RMSE 0.031 / 0.025 / 0.036 for colormip and 0.045 / 0.037 / 0.042 for filtered; with the level-0
  // variance of linearised_tap_variance, on scenes/colormap_objects.json too (sphere, mesh, head-on
  // and grazing planes; docs/colormap_filtering.md), 1 stays best.
  real lod = width > real(2) ? log2(width) - real(1) : real(0);
  bool x_longer = dot(a, a) >= dot(b, b);
  return AnisotropicFootprint(clamp(lod, real(0), levels - real(1)), taps, major * e1 / size,
                              minor * real2(-e1.y, e1.x) / size, width, x_longer ? duv_dx : duv_dy,
                              x_longer ? duv_dy : duv_dx);
}

// The variance of the bilinear texture over a tap (a parallelogram with axes a, b in level-0
// texels, uniformly weighted) from its gradient g at the tap's centre: t ~ t0 + g.(x a + y b) with
// x, y ~ U(-1/2, 1/2) gives ((g.a)^2 + (g.b)^2) / 12, exact for a linear texture. Used for taps up
// to 2 texels wide (MIP level 0); wider taps are scaled back to width 2, where trilinear lookups
// hand over to the moment chain (docs/colormap_filtering.md).
inline real linearised_tap_variance(real2 g, real2 a, real2 b) {
  real ga = dot(g, a), gb = dot(g, b);
  real width2 = max(dot(a, a), dot(b, b));
  return (ga * ga + gb * gb) / real(12) * min(real(1), real(4) / max(width2, real(1e-30)));
}

#endif
