// The per-pixel model of a colour-mapped Gaussian microsurface (Heitz et al. 2013, Filtering Color
// Mapped Textures and Surfaces; Heitz et al. 2014, Filtering Non-Linear Transfer Functions on Surfaces):
// the footprint's heights N(h_mean, h_sigma^2) and slopes N(s_mean, Sigma) from its moments,
// the visible slopes D_s and Smith's Lambda for the view, the visible heights (CDF C^(1 + Lambda_v)),
// the light's Lambda_l, and the quadrature nodes over which a shader integrates its colour maps, plus
// the LEAN-convolved Beckmann lobe. Derivation, accuracy and tests: docs/microsurface_filtering.md.
#ifndef FACET_MICROSURFACE_FILTER_GLSL
#define FACET_MICROSURFACE_FILTER_GLSL
#include "lib/prelude.glsl"
#include "lib/beckmann_facet.glsl"
#include "lib/gaussian_masking.glsl"
#include "lib/normal_over_parallelogram.glsl"
#include "lib/visible_slope.glsl"

// Nodes per axis of the Gauss-Hermite grid over D_s (MS_SLOPE_NODES_COSINE when only the cosine to the
// light is integrated, no slope colour map), and midpoint nodes of the visible-height rule.
#define MS_SLOPE_NODES 4
#define MS_SLOPE_NODES_COSINE 3
#define MS_HEIGHT_NODES 8
// The visible-height nodes as a table (renderer/precompute/visible_height_nodes.hpp): at r = log(1 + lambda) on a
// grid of MS_NODE_TABLE_STEP up to r = 70 (float's Lambda saturates at e^69, GM_LOG_LAMBDA_MAX), linear in r
// between grid points (docs/microsurface_filtering.md, "Visible-height nodes from a table").
#define MS_NODE_TABLE_STEP real(0.03125)
#define MS_NODE_TABLE_POINTS 2241
// Variance floors: a zero-variance footprint (a point) keeps every ratio of visible_slope finite; the
// floors move slopes by 1e-6 and heights by 1e-9 world units, far below what a pixel resolves.
#define MS_SLOPE_VARIANCE_MIN real(1e-12)
#define MS_HEIGHT_SIGMA_MIN real(1e-9)

struct MicrosurfaceStatistics {
  real h_mean;
  real h_sigma;
  real2 s_mean;
  real3 s_cov;  // (var_x, var_y, c_xy)
};

// From the footprint's moments m0 = (E[h], E[h^2], E[s_x], E[s_y]) and m1 = (E[s_x^2], E[s_y^2],
// E[s_x s_y], -): the Gaussians of heights and slopes, eq. (1) of Heitz et al. 2014 (LEAN mapping).
inline MicrosurfaceStatistics microsurface_statistics(real4 m0, real4 m1) {
  real h_var = max(m0.y - m0.x * m0.x, real(0));
  real var_x = max(m1.x - m0.z * m0.z, real(0)) + MS_SLOPE_VARIANCE_MIN;
  real var_y = max(m1.y - m0.w * m0.w, real(0)) + MS_SLOPE_VARIANCE_MIN;
  real c_max = sqrt(var_x * var_y);
  real c_xy = clamp(m1.z - m0.z * m0.w, -c_max, c_max);
  return MicrosurfaceStatistics(m0.x, max(sqrt(h_var), MS_HEIGHT_SIGMA_MIN), real2(m0.z, m0.w),
                                real3(var_x, var_y, c_xy));
}

// (theta, phi) of a unit direction in the plane frame (tangent, bitangent, normal); phi = 0 along the
// normal, where atan(0, 0) is undefined.
inline real2 microsurface_angles(real3 w) {
  real r = sqrt(w.x * w.x + w.y * w.y);
  return real2(atan(r, w.z), r > real(0) ? atan(w.y, w.x) : real(0));
}

// Unit facet normal of slope s = grad z: n ~ (-s_x, -s_y, 1) (Heitz et al. 2014 eq. 1's convention).
inline real3 microsurface_normal(real2 s) { return normalize(real3(-s.x, -s.y, real(1))); }

struct MicrosurfaceVisibility {
  VisibleSlope ds;  // the visible slopes for the view, eqs. (16), (42)-(46) of Heitz et al. 2014
  real lambda_v;    // Smith's Lambda of the view (docs/masking.md)
  real lambda_l;    // ... of the light
  real lit;         // P(lit | visible) = E_vis[C(h)^Lambda_l] = (1 + Lambda_v)/(1 + Lambda_v + Lambda_l)
};

// v, l: unit directions toward the viewer and the light in the plane frame (v.z > 0).
inline MicrosurfaceVisibility microsurface_visibility(MicrosurfaceStatistics s, real3 v, real3 l) {
  real2 view = microsurface_angles(v);
  real2 light = microsurface_angles(l);
  // A light below the horizon of the mean plane lights nothing (Lambda_l = inf: lit = 0). Both
  // Lambdas through one call (a shader compiler that inlines every call compiles each call site on its
  // own: docs/render_speed.md, "Pipeline set-up").
  real lambda_v = real(0), lambda_l = exp(GM_LOG_LAMBDA_MAX);
  for (int k = 0; k < (l.z > real(0) ? 2 : 1); ++k) {
    real2 w = k == 0 ? view : light;
    real lambda = gaussian_smith_lambda(s.s_mean, s.s_cov, w.x, w.y);
    if (k == 0) lambda_v = lambda; else lambda_l = lambda;
  }
  real lit = (real(1) + lambda_v) / (real(1) + lambda_v + lambda_l);
  return MicrosurfaceVisibility(visible_slope(s.s_mean, s.s_cov, view.x, view.y), lambda_v, lambda_l, lit);
}

// Node k of MS_HEIGHT_NODES of the heights with CDF C^(1 + lambda): in u = C^(1 + lambda) every
// such law is uniform on (0, 1), so E[g(h)] = int_0^1 g(h(u)) du, taken by the midpoint rule.
// lambda = Lambda_v gives the visible heights; lambda = Lambda_v + Lambda_l the visible and lit ones
// (E_vis[g C^Lambda_l] = lit * E_{C^(1 + Lambda_v + Lambda_l)}[g]).
inline real microsurface_height_node(int k, real h_mean, real h_sigma, real lambda) {
  real u = (real(k) + real(0.5)) / real(MS_HEIGHT_NODES);
  return visible_height_sample(u, h_mean, h_sigma, lambda);
}

// Where lambda falls in the node table: (grid point i, the weight of point i + 1). A NaN lambda takes point 0.
inline real2 microsurface_node_table_position(real lambda) {
  real r = log(real(1) + lambda);
  real p = r >= real(0) ? min(r / MS_NODE_TABLE_STEP, real(MS_NODE_TABLE_POINTS - 1)) : real(0);
  real i = min(floor(p), real(MS_NODE_TABLE_POINTS - 2));
  return real2(i, p - i);
}

// The lit part E_vis[g C^Lambda_l] = int_0^1 g(h(u)) u^a du, a = Lambda_l/(1 + Lambda_v), on the
// visible nodes themselves (product rule: u^a integrated exactly over node k's cell, g held constant):
// lit * sum_k g(h_k) w_k, w_k = ((k + 1)/K)^(1 + a) - (k/K)^(1 + a), sum w_k = 1. Used while a is at most
// MS_LIT_SHARED_MAX (u^a varies slowly); beyond, the weight piles into the last cell and the shader
// takes the nodes of lambda = Lambda_v + Lambda_l instead.
const real MS_LIT_SHARED_MAX = real(1);

inline real microsurface_lit_exponent(MicrosurfaceVisibility vis) {
  return vis.lambda_l / (real(1) + vis.lambda_v);
}

inline real microsurface_lit_weight(int k, real a) {
  real K = real(MS_HEIGHT_NODES);
  return pow((real(k) + real(1)) / K, real(1) + a) - pow(real(k) / K, real(1) + a);
}

struct MicrosurfaceSlopeNode {
  real2 s;
  real weight;
};

// Gauss-Hermite (probabilists') abscissa and weight i of the n-point rule, n = MS_SLOPE_NODES = 4
// (roots of He_4, x^2 = 3 -+ sqrt(6), weights 4!/(16 He_3(x)^2)) or n = MS_SLOPE_NODES_COSINE = 3
// (x = 0, -+sqrt(3), weights 2/3, 1/6).
inline real2 microsurface_hermite(int n, int i) {
  if (n == 3) {
    real x3 = i == 1 ? real(0) : real(1.7320508075688772);
    return real2(i == 0 ? -x3 : x3, i == 1 ? real(2) / real(3) : real(1) / real(6));
  }
  real x = i == 0 || i == 3 ? real(2.3344142183389773) : real(0.74196378430272586);
  real w = i == 0 || i == 3 ? real(0.045875854768068492) : real(0.45412414523193151);
  return real2(i < 2 ? -x : x, w);
}

// Node (i, j) of the n x n Gauss-Hermite grid over the Gaussian approximation N(mean, cov) of D_s: the
// standard grid mapped through the Cholesky factor of cov.
inline MicrosurfaceSlopeNode microsurface_slope_node(VisibleSlope ds, int n, int i, int j) {
  real2 a = microsurface_hermite(n, i);
  real2 b = microsurface_hermite(n, j);
  real l00 = sqrt(ds.cov.x);
  real l10 = l00 > real(0) ? ds.cov.z / l00 : real(0);
  real l11 = sqrt(max(ds.cov.y - l10 * l10, real(0)));
  return MicrosurfaceSlopeNode(ds.mean + real2(l00 * a.x, l10 * a.x + l11 * b.x), a.y * b.y);
}

// The slope distribution N(mean, cov) as a normal distribution per steradian at the unit half vector h
// (h.z > 0): p(slope of h) / h_z^4, the determinant of cov kept at least det_min; p averaged over the
// pixel (normal_density_over_parallelogram) where its steps (xy: per pixel step along x, zw: along y) are
// not 0, else taken at h.
inline real microsurface_slope_ndf(real3 h, real2 mean, real3 cov, real det_min, real4 pixel_steps) {
  real2 s = real2(-h.x / h.z, -h.y / h.z);
  real h4 = h.z * h.z * h.z * h.z;
  if (pixel_steps != real4(0))
    return normal_density_over_parallelogram(s, real2(pixel_steps.x, pixel_steps.y), real2(pixel_steps.z, pixel_steps.w),
                                            mean, cov, det_min) / h4;
  real2 d = s - mean;
  real det = max(cov.x * cov.y - cov.z * cov.z, det_min);
  real q = (cov.y * d.x * d.x - real(2) * cov.z * d.x * d.y + cov.x * d.y * d.y) / det;
  real h2 = h.z * h.z;
  return real(0.5) * FACET_INV_PI * exp(real(-0.5) * q) / (sqrt(det) * h2 * h2);
}

// The slope of the direction w (-w.xy/w.z), w.z kept at least 1e-3 |w|: a view or normal below the horizon
// (a neighbouring pixel's, at grazing angles or beyond a silhouette) gives a large, finite slope.
inline real2 horizon_safe_slope(real3 w) {
  real z = max(w.z, real(1e-3) * length(w));
  return real2(-w.x / z, -w.y / z);
}

// The half vector's slope steps over a pixel (xy: toward the neighbouring pixel along x, zw: along y):
// l, v in the lobe's frame (l.z > 0), v_x and v_y the views one pixel step away (the neighbouring camera
// rays); each half vector's slope is that of l + v.
inline real4 microsurface_pixel_half_slope_steps(real3 l, real3 v, real3 v_x, real3 v_y) {
  real2 s = horizon_safe_slope(l + v);
  return real4(horizon_safe_slope(l + v_x) - s, horizon_safe_slope(l + v_y) - s);
}

// The slope covariance (var_x, var_y, c_xy) of a Beckmann lobe of roughness alpha: N(0, alpha^2/2).
inline real3 microsurface_lobe_cov(real2 alpha) {
  return real3(real(0.5) * alpha.x * alpha.x, real(0.5) * alpha.y * alpha.y, real(0));
}

// What the slope-space lobe leaves out at a facet of slope s: its own Beckmann lobe at h in its frame over the
// sheared one, exp(q_shear - q_facet) (h_z / h'_z)^4, times its own G2 there; 0 where l, v or h lies below it.
inline real microsurface_facet_lobe_at(real2 s, real2 alpha, real3 l, real3 v, real3 h, real2 s_h) {
  BeckmannFacetFrame f = beckmann_facet_frame(normalize(real3(-s.x, -s.y, real(1))), real3(1, 0, 0));
  real3 wi = beckmann_facet_local(f, l), wo = beckmann_facet_local(f, v), hf = beckmann_facet_local(f, h);
  if (!(wi.z > real(0) && wo.z > real(0) && hf.z > real(0))) return real(0);
  real2 d = s_h - s, t = real2(hf.x, hf.y) / hf.z;
  real q_shear = d.x * d.x / (alpha.x * alpha.x) + d.y * d.y / (alpha.y * alpha.y);
  real q_facet = t.x * t.x / (alpha.x * alpha.x) + t.y * t.y / (alpha.y * alpha.y);
  real log_ratio = q_shear - q_facet + real(4) * log(h.z / hf.z);  // a facet h grazes reads exp(-inf) = 0
  return exp(min(log_ratio, real(80))) * beckmann_facet_g2(wi, wo, alpha);
}

// The facets whose lobes reach the half vector h, in their own frames (eq. M8' of docs/microsurface_filtering.md).
// In slope space the footprint's facets N(s_mean, cov) times the lobe N(s_h - s; 0, lobe) is the convolved
// density at s_h times the law of the facet slope s given h, N(mu, P), P = cov (cov + lobe)^-1 lobe,
// mu = lobe (cov + lobe)^-1 s_mean + cov (cov + lobe)^-1 s_h. The factor is the mean over that law of
// microsurface_facet_lobe_at, which vanishes past the facets that turn l or v below their horizon: the
// half-planes s . w_xy < w_z (w = l, v), at grazing angles a strip narrower than the law. In whitened
// coordinates z (s = mu + L z) the axis e1 is the tighter half-plane's normal: along it the allowed interval
// [lo, hi] at each of 3 Gauss-Hermite nodes z2 across is exact, and the mean over it is taken at the truncated
// normal's mean +- its standard deviation (exact for quadratics). A point footprint (cov -> 0) gives
// microsurface_facet_lobe_at the mean facet.
inline real microsurface_facet_lobe_factor(real2 s_mean, real3 cov, real2 alpha, real3 l, real3 v) {
  real3 lobe = microsurface_lobe_cov(alpha);
  real3 h = normalize(l + v);
  real2 s_h = real2(-h.x / h.z, -h.y / h.z);
  real2x2 c = real2x2(cov.x, cov.z, cov.z, cov.y);
  real2x2 g = real2x2(lobe.x, lobe.z, lobe.z, lobe.y);
  real2x2 sum_inverse = inverse(c + g);
  real2x2 p = c * sum_inverse * g;
  real2 mu = g * (sum_inverse * s_mean) + c * (sum_inverse * s_h);
  real l00 = sqrt(max(p[0][0], real(0)));
  real l10 = l00 > real(0) ? real(0.5) * (p[0][1] + p[1][0]) / l00 : real(0);
  real l11 = sqrt(max(p[1][1] - l10 * l10, real(0)));
  real2x2 chol = real2x2(l00, l10, real(0), l11);  // columns: s - mu = chol z
  // The half-planes a_k . z < b_k of l and v: a_k = chol^T w_xy, b_k = w_z - mu . w_xy.
  real2 a_l = transpose(chol) * real2(l.x, l.y), a_v = transpose(chol) * real2(v.x, v.y);
  real b_l = l.z - dot(mu, real2(l.x, l.y)), b_v = v.z - dot(mu, real2(v.x, v.y));
  real margin_l = b_l / max(length(a_l), real(1e-30)), margin_v = b_v / max(length(a_v), real(1e-30));
  real2 axis = margin_l <= margin_v ? a_l : a_v;
  real2 e1 = length(axis) > real(0) ? normalize(axis) : real2(1, 0), e2 = real2(-e1.y, e1.x);
  real factor = real(0);
  for (int j = 0; j < MS_SLOPE_NODES_COSINE; ++j) {
    real2 node = microsurface_hermite(MS_SLOPE_NODES_COSINE, j);
    real lo = real(-40), hi = real(40);
    bool empty = false;
    for (int k = 0; k < 2; ++k) {
      real2 a = k == 0 ? a_l : a_v;
      real along = dot(a, e1), rest = (k == 0 ? b_l : b_v) - dot(a, e2) * node.x;
      if (along > real(0)) hi = min(hi, rest / along);
      else if (along < real(0)) lo = max(lo, rest / along);
      else empty = empty || !(rest > real(0));
    }
    if (empty || !(lo < hi)) continue;
    // Phi(hi) - Phi(lo) from the tails on the side where they are small, the truncated normal's mean and
    // variance (kept within the interval's).
    real pdf_lo = sf_normal_pdf(lo), pdf_hi = sf_normal_pdf(hi);
    real mass = lo >= real(0) ? sf_normal_tail(lo) - sf_normal_tail(hi)
                : hi <= real(0) ? sf_normal_tail(-hi) - sf_normal_tail(-lo)
                                : real(1) - sf_normal_tail(hi) - sf_normal_tail(-lo);
    if (!(mass > real(1e-30))) continue;
    real mean = clamp((pdf_lo - pdf_hi) / mass, lo, hi);
    real second = real(1) + (lo * pdf_lo - hi * pdf_hi) / mass;
    real sd = sqrt(clamp(second - mean * mean, real(0), real(0.25) * (hi - lo) * (hi - lo)));
    real inner = real(0);
    for (int side = -1; side <= 1; side += 2) {
      real z1 = clamp(mean + real(side) * sd, lo, hi);
      inner += microsurface_facet_lobe_at(mu + chol * (z1 * e1 + node.x * e2), alpha, l, v, h, s_h);
    }
    factor += node.y * mass * real(0.5) * inner;
  }
  return factor;
}

// The Beckmann lobe (roughness alpha along the plane's tangent and bitangent) on the footprint's
// slopes, LEAN-convolved (Olano and Baker 2010): slopes N(s_mean, Sigma + alpha^2/2). Returns
// f cos_i = D(h) G2 F/(4 cos_o) with D(h) = p(slope of h)/h_z^4, G2 = 1/(1 + Lambda_i + Lambda_o) the
// height-correlated masking-shadowing of the footprint's own slopes N(s_mean, Sigma) and F the facets' own lobes
// and masking in their frames (microsurface_facet_lobe_factor, eq. M8'); 0 when l or v is below the plane. D is
// averaged over the pixel whose half-vector slope steps are pixel_steps (microsurface_pixel_half_slope_steps; 0:
// D at the pixel's centre alone); G2 and F, smooth over a pixel, are taken at its centre.
inline real microsurface_specular(MicrosurfaceStatistics s, real2 alpha, real3 l, real3 v, real4 pixel_steps) {
  if (l.z <= real(0) || v.z <= real(0)) return real(0);
  real3 cov = s.s_cov + microsurface_lobe_cov(alpha);
  real D = microsurface_slope_ndf(normalize(l + v), s.s_mean, cov, real(0.25) * alpha.x * alpha.x * alpha.y * alpha.y,
                                  pixel_steps);
  real2 light = microsurface_angles(l);
  real2 view = microsurface_angles(v);
  real G2 = gaussian_smith_g2(s.s_mean, s.s_cov, light.x, light.y, view.x, view.y);
  return D * G2 * microsurface_facet_lobe_factor(s.s_mean, s.s_cov, alpha, l, v) / (real(4) * v.z);
}

// beckmann_facet_specular with D averaged over the pixel (eq. P2): the facet's Beckmann slopes
// N(0, alpha^2/2) over the pixel's half vectors relative to the pixel's own facet normals. Its views are v at
// the centre and v_x, v_y one pixel step away; its normals n at the centre and n_xp, n_xm, n_yp, n_ym one
// step away on each side (a bilinear patch's normal turns across a pixel that spans part of a texel). To
// first order the half vector's slope relative to a neighbour's normal is its slope less the normal's, both
// in n's frame (eq. P3), the normals' turn taken on each axis's smaller side (smaller_pixel_step). Unit,
// world space like n, tangent, v and l. G2 is the facet's, at the centre.
inline real beckmann_facet_specular_over_pixel(real3 n, real3 tangent, real3 v, real3 l, real2 alpha, real3 v_x,
                                               real3 v_y, real3 n_xp, real3 n_xm, real3 n_yp, real3 n_ym) {
  BeckmannFacetFrame f = beckmann_facet_frame(n, tangent);
  real3 wi = beckmann_facet_local(f, l);
  real3 wo = beckmann_facet_local(f, v);
  if (!(wi.z > real(0) && wo.z > real(0))) return real(0);
  real4 steps = microsurface_pixel_half_slope_steps(wi, wo, beckmann_facet_local(f, v_x), beckmann_facet_local(f, v_y));
  real2 turn_x = smaller_pixel_step(horizon_safe_slope(beckmann_facet_local(f, n_xp)),
                                    horizon_safe_slope(beckmann_facet_local(f, n_xm)));
  real2 turn_y = smaller_pixel_step(horizon_safe_slope(beckmann_facet_local(f, n_yp)),
                                    horizon_safe_slope(beckmann_facet_local(f, n_ym)));
  steps -= real4(turn_x, turn_y);
  real3 lobe = microsurface_lobe_cov(alpha);
  real D = microsurface_slope_ndf(normalize(wi + wo), real2(0), lobe, lobe.x * lobe.y, steps);
  return D * beckmann_facet_g2(wi, wo, alpha) / (real(4) * wo.z);
}

#endif
