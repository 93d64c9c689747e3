// The mean of a 2-D normal density over a parallelogram, the box filter of a pixel over which the
// density's argument moves linearly (docs/microsurface_filtering.md, eq. P2): shared by the microsurface
// and microflake lobes over the pixel and by the diffraction orders over the pixel.
#ifndef FACET_NORMAL_OVER_PARALLELOGRAM_GLSL
#define FACET_NORMAL_OVER_PARALLELOGRAM_GLSL
#include "lib/prelude.glsl"
#include "lib/special_functions.glsl"

// The mean of the standard normal density over [x - w/2, x + w/2] (w >= 0): (Phi(x + w/2) - Phi(x - w/2))/w,
// from the upper tails on x's side (no difference of two numbers near 1), each from one exp and the coarse
// tail (lib/special_functions.glsl; absolute error below 7.5e-8, smooth in x, so a difference over a
// short interval does not amplify it); below w = 1e-2 its Taylor form phi(x) (1 + (x^2 - 1) w^2/24), whose
// next term is below 1e-8 relative for |x| < 10, where the difference of the tails would lose digits.
inline real box_normal_mean(real x, real w) {
  real a = abs(x);
  if (w < real(1e-2)) return sf_normal_pdf(a) * (real(1) + (a * a - real(1)) * w * w / real(24));
  real lo = a - real(0.5) * w, hi = a + real(0.5) * w;
  real tail_lo = sf_normal_tail_coarse(abs(lo), exp(real(-0.5) * lo * lo));
  real tail_hi = sf_normal_tail_coarse(hi, exp(real(-0.5) * hi * hi));
  return (lo >= real(0) ? tail_lo - tail_hi : real(1) - tail_lo - tail_hi) / w;
}

// L^-1 v for the lower-triangular L = [[l00, 0], [l10, l11]]: v in whitened slopes.
inline real2 cholesky_whiten(real2 v, real l00, real l10, real l11) {
  return real2(v.x / l00, (v.y - l10 * v.x / l00) / l11);
}

// The density N(mean, cov) averaged over the parallelogram s0 + step_x a + step_y b, a, b in [-1/2, 1/2]:
// a pixel (box filter) of whatever moves linearly across it, s0 at its centre and step_x, step_y its change
// per pixel step (the half vector's slopes: eq. P2 of docs/microsurface_filtering.md; a diffraction order's
// (u, v): eq. O2 of docs/diffraction_fast_paths.md). cov's determinant is kept at
// least det_min. Whitened by cov's Cholesky factor the density is phi(x) phi(y) and the parallelogram
// c + k1 a + k2 b; x runs along the longer edge k1, y across it. Integrated exactly over a, the edge k1
// gives the mean of phi over a width |k1| (box_normal_mean); over b, the weight phi(c_y + b k2_y)
// is integrated exactly and the offset k2_x b along x taken at its mean under that weight, its spread
// added to x's variance. Exact for a point pixel (steps 0: the density at s0), for edges orthogonal after
// whitening, and in the limit of a lobe far narrower than the pixel along both edges.
inline real normal_density_over_parallelogram(real2 s0, real2 step_x, real2 step_y, real2 mean, real3 cov,
                                             real det_min) {
  real det = max(cov.x * cov.y - cov.z * cov.z, det_min);
  real l00 = sqrt(cov.x), l10 = cov.z / l00, l11 = sqrt(det) / l00;  // cov = L L^T (determinant det)
  real2 c = cholesky_whiten(s0 - mean, l00, l10, l11);
  real2 ka = cholesky_whiten(step_x, l00, l10, l11), kb = cholesky_whiten(step_y, l00, l10, l11);
  bool a_longer = dot(ka, ka) >= dot(kb, kb);
  real2 k1 = a_longer ? ka : kb, k2 = a_longer ? kb : ka;
  real width = length(k1);
  real2 e1 = width > real(0) ? k1 / width : real2(1, 0), e2 = real2(-e1.y, e1.x);
  real cx = dot(c, e1), cy = dot(c, e2), k2x = dot(k2, e1), k2y = abs(dot(k2, e2));
  cy = dot(k2, e2) < real(0) ? -cy : cy;  // b -> -b makes k2y >= 0 (the box is symmetric)
  // The weight phi(cy + b k2y) on b in [-1/2, 1/2]: its integral, and the mean and variance of b under it.
  real across = box_normal_mean(cy, k2y);
  real b_mean = -cy * k2y / real(12), b_var = real(1) / real(12);  // k2y -> 0: uniform to first order
  if (k2y >= real(1e-2)) {
    real lo = cy - real(0.5) * k2y, hi = cy + real(0.5) * k2y;
    real z = max(across * k2y, real(1e-30));
    real y_mean = (sf_normal_pdf(lo) - sf_normal_pdf(hi)) / z;
    real y_square = real(1) + (lo * sf_normal_pdf(lo) - hi * sf_normal_pdf(hi)) / z;
    b_mean = clamp((y_mean - cy) / k2y, real(-0.5), real(0.5));
    b_var = clamp((y_square - y_mean * y_mean) / (k2y * k2y), real(0), real(1) / real(12));
  }
  real spread = sqrt(real(1) + k2x * k2x * b_var);
  real along = box_normal_mean((cx + b_mean * k2x) / spread, width / spread) / spread;
  return across * along / sqrt(det);
}

// A pixel's step along one axis from its neighbours on both sides (to_plus toward the next pixel, to_minus toward
// the previous one): the one-sided step of the smaller length, the side where the pixel's normals turn less. The
// parallelogram of eq. P2 is symmetric about the centre and mirrors the step onto the other side; where the
// outer neighbour lies beyond a silhouette or a bilinear patch's crease its normal is not the pixel's, and
// mirrored it swept a highlight into pixels that have none (docs/microflake_brdf.md, F3).
inline real2 smaller_pixel_step(real2 to_plus, real2 to_minus) {
  return dot(to_plus, to_plus) <= dot(to_minus, to_minus) ? to_plus : -to_minus;
}

#endif
