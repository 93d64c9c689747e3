// Stam's diffraction BRDF for a periodically tiled height-field patch seen through a Gaussian
// spatial-coherence window, evaluated from precomputed DFTs of powers of the height
// (Single 2014, appendix B and C.1; derivation, normalisation and tests: docs/diffraction.md).
//
// Each side (GLSL storage buffer, C++ vector) fetches the table coefficients itself
// (diffraction_table.glsl) and feeds them to the functions here:
//   g = diffraction_geometry(...)
//   for every DFT bin j near k(u, v):   weight = diffraction_window_weight(...)
//       t = diffraction_taylor_start(g, H_0(j)); for n = 1..N-1: t = diffraction_taylor_step(t, g, H_n(j))
//       field = diffraction_field_add(field, weight, t)
//   diffraction_value(g, field, ...)
#ifndef FACET_DIFFRACTION_BRDF_GLSL
#define FACET_DIFFRACTION_BRDF_GLSL
#include "lib/prelude.glsl"

struct DiffractionGeometry {
  real k;             // wavenumber 2 pi / lambda [1/nm]
  real2 alpha;        // k (u, v), (u, v, w) = -wi - wr (B.5) [1/nm]
  real w;             // -(cos theta_i + cos theta_r) <= 0 (D.2)
  real w_resolved;    // w, kept at least the window's angular resolution 1/(k sigma) away from 0
  real one_plus_cos;  // 1 + wi.wr = (u^2 + v^2 + w^2) / 2, exact and free of cancellation
  real cos_i;         // cos theta_i and cos theta_r, floored at the same resolution
  real cos_r;
  real x;             // the Taylor variable k w h_s (h_s: the tables' height unit)
  real k_hs;          // k h_s
};

// wi, wr: unit vectors toward the light and the viewer, z up, z >= 0.
inline DiffractionGeometry diffraction_geometry(real3 wi, real3 wr, real lambda_nm, real sigma_nm, real hs_nm) {
  real k = real(2) * FACET_PI / lambda_nm;
  real3 uvw = -wi - wr;
  // Below 1/(k sigma) a coherence area of size sigma cannot tell a direction from grazing: the
  // floor keeps B.12's 1/w^2 and 1/(cos_i cos_r) finite (docs/errata.md#grazing-singularity) without changing resolved values.
  real resolution = real(1) / (k * sigma_nm);
  real w = min(uvw.z, real(0));
  return DiffractionGeometry(k, k * real2(uvw.x, uvw.y), w, min(w, -resolution), real(0.5) * dot(uvw, uvw),
                             max(wi.z, resolution), max(wr.z, resolution), k * w * hs_nm, k * hs_nm);
}

// Centre frequency 2 pi j / T of DFT bin j of a patch of period T.
inline real2 diffraction_bin_frequency(int jx, int jy, real period_nm) {
  return (real(2) * FACET_PI / period_nm) * real2(real(jx), real(jy));
}

// The bin nearest to the frequency alpha (rounded per axis).
inline int diffraction_nearest_bin(real alpha, real period_nm) {
  return int(floor(alpha * period_nm / (real(2) * FACET_PI) + real(0.5)));
}

// The DFT bins the window sum visits around the frequency alpha: those within r bins (per axis) of
// the nearest one that are multiples of `stride`, row by row (j_y outer). Stride 1 is every bin (the
// spectral path). A patch that repeats P_x, P_y times along x, y has non-zero coefficients only at
// multiples of (P_x, P_y), its lattice of orders, so a stride of (P_x, P_y) skips exactly the bins
// whose coefficients vanish (the orders path; docs/diffraction_fast_paths.md, F.12).
struct DiffractionWindowBins {
  ivec2 first;
  ivec2 count;  // bins per axis (0: none)
  ivec2 stride;
};

inline DiffractionWindowBins diffraction_window_bins(real2 alpha, real period_nm, int r, ivec2 stride) {
  ivec2 nearest = ivec2(diffraction_nearest_bin(alpha.x, period_nm), diffraction_nearest_bin(alpha.y, period_nm));
  real2 s = real2(stride);
  ivec2 lo = ivec2(ceil(real2(nearest - ivec2(r, r)) / s));  // in units of the stride: exact for these small integers
  ivec2 hi = ivec2(floor(real2(nearest + ivec2(r, r)) / s));
  return DiffractionWindowBins(lo * stride, max(hi - lo + ivec2(1, 1), ivec2(0, 0)), stride);
}

// The b-th bin, b < count.x * count.y.
inline ivec2 diffraction_window_bin(DiffractionWindowBins w, int b) {
  return w.first + ivec2(b % w.count.x, b / w.count.x) * w.stride;
}

// Fourier transform of the Gaussian window exp(-|x|^2 / (2 sigma^2)) at frequency offset delta,
// divided by its peak 2 pi sigma^2 (that factor is applied in diffraction_value).
inline real diffraction_window_weight(real2 delta, real sigma_nm) {
  return exp(real(-0.5) * sigma_nm * sigma_nm * dot(delta, delta));
}

inline real2 diffraction_complex_mul(real2 a, real2 b) {
  return real2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x);
}

// The Taylor sum P = sum_n (i x)^n / n! H_n (C.1), split as P = H_0 + w * rest so that P / w =
// H_0 / w + rest stays regular as w -> 0: rest = sum_{n >= 1} (i k h_s)^n w^(n-1) / n! H_n.
struct DiffractionTaylor {
  real2 specular;  // H_0: the flat part, non-zero only at bin 0 (the height is mean-free)
  real2 rest;
  real2 power;     // (i k h_s)^n w^(n-1) / n! for the next n
  real n;
};

inline DiffractionTaylor diffraction_taylor_start(DiffractionGeometry g, real2 h0) {
  return DiffractionTaylor(h0, real2(real(0), real(0)), real2(real(0), g.k_hs), real(1));
}

inline DiffractionTaylor diffraction_taylor_step(DiffractionTaylor t, DiffractionGeometry g, real2 hn) {
  real2 rest = t.rest + diffraction_complex_mul(t.power, hn);
  real2 power = real2(-t.power.y, t.power.x) * (g.x / (t.n + real(1)));  // times i x / (n + 1)
  return DiffractionTaylor(t.specular, rest, power, t.n + real(1));
}

// The windowed transform sums the bins' Taylor sums with their window weights.
struct DiffractionField {
  real2 specular;
  real2 rest;
};

inline DiffractionField diffraction_field_add(DiffractionField f, real weight, DiffractionTaylor t) {
  return DiffractionField(f.specular + weight * t.specular, f.rest + weight * t.rest);
}

struct DiffractionValue {
  real brdf;  // [1/sr]
  real P2;    // <|P(ku, kv)|^2> / A [nm^2], the power-spectrum factor of B.12
};

// Schlick's reflectance (D.1) at cos theta_h = H.V = sqrt((1 + wi.wr) / 2); it does not depend on lambda.
inline real diffraction_schlick_reflectance(DiffractionGeometry g, real R0) {
  real one_minus_cos_h = real(1) - sqrt(real(0.5) * g.one_plus_cos);
  real one_minus_cos_h2 = one_minus_cos_h * one_minus_cos_h;
  return R0 + (real(1) - R0) * one_minus_cos_h2 * one_minus_cos_h2 * one_minus_cos_h;
}

// B.12 with A = pi sigma^2 (the window's area), P = 2 pi sigma^2 S and F^2 = Schlick's
// reflectance (D.1) at cos theta_h = H.V = sqrt((1 + wi.wr) / 2):
//   P2   = 4 pi sigma^2 |S|^2
//   BRDF = k^2 R (1 + wi.wr)^2 / (4 pi^2 w^2 cos_i cos_r) P2 = k^2 R (1 + wi.wr)^2 sigma^2 |S/w|^2 / (pi cos_i cos_r)
inline DiffractionValue diffraction_value(DiffractionGeometry g, DiffractionField f, real sigma_nm, real R0) {
  real2 S = f.specular + g.w * f.rest;
  real2 S_over_w = f.specular / g.w_resolved + f.rest;
  real P2 = real(4) * FACET_PI * sigma_nm * sigma_nm * dot(S, S);
  real R = diffraction_schlick_reflectance(g, R0);
  real ks = g.k * sigma_nm * g.one_plus_cos;
  real brdf = R * ks * ks * dot(S_over_w, S_over_w) * FACET_INV_PI / (g.cos_i * g.cos_r);
  return DiffractionValue(brdf, P2);
}

#endif
