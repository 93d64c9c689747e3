// The lobe of a microflake half-space averaged over a pixel (docs/microflake_brdf.md, "The lobe over the
// pixel", eqs. F1-F3): across a pixel the shading normal turns (a sphere's curvature) and the view with it,
// so the half vector sweeps a patch of the normal frame's slopes; a lobe narrower than that patch, taken at
// the pixel's centre alone, is a highlight that aliases. Each distribution's slope density near its peak is
// a mixture of normal densities (exact for Beckmann), averaged exactly over the pixel's parallelogram of slopes
// (normal_density_over_parallelogram); what the mixture misses is taken at the centre where the pixel is small.
#ifndef FACET_MICROFLAKE_PIXEL_LOBE_GLSL
#define FACET_MICROFLAKE_PIXEL_LOBE_GLSL
#include "lib/prelude.glsl"
#include "lib/cross_section.glsl"
#include "lib/microflake_brdf.glsl"
#include "lib/microflake_shading.glsl"
#include "lib/microsurface_filter.glsl"

#define MICROFLAKE_LOBE_COMPONENTS 8

// The distribution's slope density near its peak as a mixture of isotropic normal densities of the slopes
// (eq. F1): component k (weight, per-axis variance) = (e^-mu mu du, scale/mu) for GGX, (e^-mu du / L, scale/mu)
// for KK, mu = exp(lo + (k + 1/2) du), k < components; Beckmann and SG are their one core component.
//   Beckmann: N(0, alpha^2/2), exact;
//   SG: D ~ kappa/(2 pi) exp(-kappa theta^2/2) near the pole, N(0, 1/kappa);
//   GGX: (1 + r^2/alpha^2)^-2/(pi alpha^2) = integral e^-l N(0, alpha^2/(2 l)) dl
//        = integral e^-l l N(0, alpha^2/(2 l)) d(log l), l from 1e-3 (22 alpha wide) to 20;
//   KK: D ~ 1/(pi L (c^2 + r^2)), c^2 = 2(1 - b)/b, = (1/L) integral e^-mu N(0, c^2/(2 mu)) d(log mu),
//       mu from c^2 (slopes of about 1, where the pole's form ends) to 20;
// both integrals by the midpoint rule in the logarithm, MICROFLAKE_LOBE_COMPONENTS steps, the components a
// factor of at most 2.7 apart in width. core_variance: the core's, alpha^2/2 (Beckmann, SG, GGX) or c^2/2 (KK),
// the scale below which the mixture's residual varies (eq. F2).
struct MicroflakeLobeMixture {
  bool single;  // Beckmann, SG: the core is the one component
  bool ggx;
  int components;
  real lo, du, kk_norm, variance_scale, core_variance;  // kk_norm: KK's L
};

inline MicroflakeLobeMixture microflake_lobe_mixture(int ndf, real param) {
  real core = real(0.5) * param * param;
  if (ndf == NDF_BECKMANN || ndf == NDF_SG)
    return MicroflakeLobeMixture(true, false, 1, real(0), real(0), real(1), core, core);
  bool ggx = ndf == NDF_GGX;
  real b = ndf_kk_clamp_b(param);
  real c2 = real(2) * (real(1) - b) / b;  // KK's pole width squared
  real lo = ggx ? log(real(1e-3)) : log(c2), hi = log(real(20));
  int components = lo < hi ? MICROFLAKE_LOBE_COMPONENTS : 0;  // a KK lobe a radian wide or more: no pole to filter
  return MicroflakeLobeMixture(false, ggx, components, lo, (hi - lo) / real(MICROFLAKE_LOBE_COMPONENTS),
                               ggx ? real(1) : ndf_kk_norm(b), ggx ? core : real(0.5) * c2,
                               ggx ? core : (real(1) - b) / b);
}

// Component k < mixture.components as (weight, per-axis variance).
inline real2 microflake_lobe_component(MicroflakeLobeMixture mixture, int k) {
  if (mixture.single) return real2(1, mixture.core_variance);
  real mu = exp(mixture.lo + (real(k) + real(0.5)) * mixture.du);
  real weight = mixture.ggx ? exp(-mu) * mu * mixture.du : exp(-mu) * mixture.du / mixture.kk_norm;
  return real2(weight, mixture.variance_scale / mu);
}

// The point of the parallelogram s0 + a k1 + b k2, a, b in [-1/2, 1/2], nearest the origin (the lobe's peak).
inline real2 microflake_nearest_slope(real2 s0, real2 k1, real2 k2) {
  real det = k1.x * k2.y - k1.y * k2.x;
  if (abs(det) > real(1e-30)) {  // the origin inside: itself
    real a = (k2.x * s0.y - k2.y * s0.x) / det, b = (k1.y * s0.x - k1.x * s0.y) / det;
    if (abs(a) <= real(0.5) && abs(b) <= real(0.5)) return real2(0);
  }
  real2 best = s0;
  for (int edge = 0; edge < 4; ++edge) {  // else on an edge: each edge's nearest point
    real2 along = edge < 2 ? k1 : k2;
    real2 start = s0 + (edge < 2 ? k2 : k1) * (edge % 2 == 0 ? real(-0.5) : real(0.5)) - real(0.5) * along;
    real t = clamp(-dot(start, along) / max(dot(along, along), real(1e-30)), real(0), real(1));
    real2 q = start + t * along;
    best = dot(q, q) < dot(best, best) ? q : best;
  }
  return best;
}

// D(h) averaged over the pixel whose half-vector slopes (in the normal's frame, relative to the pixel's own
// normals) step by pixel_steps (xy: toward the neighbouring pixel along x, zw: along y; 0: D at h alone), eq. F2:
//   D_pixel = (sum_k w_k <N_k>_pixel + g R(s)) / h_z(s_h)^4,   s = -h.xy/h.z,
//   s_h = s_near + (s - s_near) v/(v + |s - s_near|^2)   (v: the core's variance),
//   R(s) = D(h) h_z^4 - sum_k w_k N_k(s)   (the slope density less its mixture, at the pixel's centre),
//   g = min(1, <N_core>_pixel / N_core(s)),
// kept at least 0. The mixture's mean over the pixel is exact (normal_density_over_parallelogram); its residual
// R, which varies on the core's scale, is taken at the centre where the pixel is small against the core
// (g = 1) and fades where the pixel averages the core away (g -> 0; R integrates to about 0). D is the slope
// density over h_z^4, taken where the pixel's share of the lobe lies: at the centre for a pixel small against
// the core, at s_near, the pixel's slope nearest the peak, for a lobe narrower than the pixel. Exact for a
// point pixel, and for Beckmann but for h_z's variation across the pixel; for the others the error is also
// what g does not model of R (tests/kernels/microflake_pixel_lobe_test.cpp).
inline real microflake_D_over_pixel(int ndf, real param, real3 h, real4 pixel_steps) {
  real D = ndf_D(ndf, h, param);
  if (pixel_steps == real4(0) || !(h.z > real(0))) return D;
  real2 s = real2(-h.x / h.z, -h.y / h.z);
  real2 step_x = real2(pixel_steps.x, pixel_steps.y), step_y = real2(pixel_steps.z, pixel_steps.w);
  real h2 = h.z * h.z;
  real residual = D * h2 * h2, mixture = real(0), core = real(0), core_point = real(0);
  // One call of the pixel density in a loop of the distribution's count (lavapipe inlines each call site,
  // and would unroll a loop of constant trips): the components, then the core where it is none of them.
  MicroflakeLobeMixture lobe = microflake_lobe_mixture(ndf, param);
  int trips = lobe.single ? 1 : lobe.components + 1;
  for (int k = 0; k < trips; ++k) {
    bool is_core = !lobe.single && k == lobe.components;
    real2 c = is_core ? real2(0, lobe.core_variance) : microflake_lobe_component(lobe, k);
    real v = c.y;
    real pixel = normal_density_over_parallelogram(s, step_x, step_y, real2(0), real3(v, v, 0), v * v);
    real point = real(0.5) * FACET_INV_PI * exp(real(-0.5) * dot(s, s) / v) / v;
    mixture += c.x * pixel;
    residual -= c.x * point;
    core = is_core || lobe.single ? pixel : core;
    core_point = is_core || lobe.single ? point : core_point;
  }
  real v_core = lobe.core_variance;
  real g = core < core_point ? core / core_point : real(1);
  real2 near = microflake_nearest_slope(s, step_x, step_y);
  real2 outward = s - near;
  near += v_core / (v_core + dot(outward, outward)) * outward;  // the centre where the pixel is small against the core
  real near_z2 = real(1) / (real(1) + dot(near, near));  // h_z^2 at that slope
  return max((mixture + g * residual) / (near_z2 * near_z2), real(0));
}

// The slope of a direction in the frame of the normal n (to_normal_frame; horizon_safe_slope).
inline real2 microflake_frame_slope(real3 n, real3 w) { return horizon_safe_slope(to_normal_frame(n, w)); }

// The half vector's slope step toward one neighbouring pixel (eq. F3) in the frame of the pixel's normal n,
// relative to the normal each point of the pixel has: to first order the slope of the half vector of l and the
// neighbour's view v_q less the slope of the neighbour's normal n_q, both in n's frame, less the centre's,
// centre = microflake_frame_slope(n, l + v) (taken once for a pixel's four neighbours).
inline real2 microflake_half_slope_step(real3 n, real3 l, real2 centre, real3 n_q, real3 v_q) {
  return microflake_frame_slope(n, l + v_q) - microflake_frame_slope(n, n_q) - centre;
}

// microflake_radiance with D averaged over the pixel (eq. F2); the BRDF's denominator (the cross-sections),
// smooth over a pixel, at its centre.
inline real3 microflake_radiance_over_pixel(int ndf, real param, real3 albedo, real3 n, real3 v, real3 l,
                                            real3 light_irradiance, real visibility, real3 ambient_irradiance,
                                            real4 pixel_steps) {
  real3 wi = to_normal_frame(n, l);
  real3 wo = to_normal_frame(n, v);
  real f = real(0);
  if (wi.z > real(0) && wo.z > real(0))
    f = microflake_D_over_pixel(ndf, param, normalize(wi + wo), pixel_steps) /
        (real(4) * microflake_brdf_denominator(ndf, param, wi, wo));
  return microflake_shade(albedo, f, wi.z, light_irradiance, visibility, ambient_irradiance);
}

#endif
