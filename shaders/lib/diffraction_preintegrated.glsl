// Pre-integrated diffraction colour (after Dhillon et al. 2014; derivation, error budget and tests:
// docs/diffraction_fast_paths.md). The windowed Taylor sum S = sum_n (w - w_c)^n d_n(k, u, v) makes
// k^2 |S|^2 a polynomial of degree 2N - 2 in delta = w - w_c whose coefficients depend only on
// (u, v) and k. Integrated against the light's spectrum and the CIE observer at precompute they
// become 2N - 1 real XYZ tables T_p(u, v) (eq. F.4), and shading is
//   XYZ = R sigma^2 (1 + wi.wr)^2 / (pi cos_i cos_r w^2) * sum_p delta^p T_p(u, v)     (eq. F.5)
// with no wavelength loop. Each side fetches the table words itself (GLSL storage buffer, C++
// vector) and feeds them to the functions here:
//   g = diffraction_geometry(wi, wr, floor_lambda, sigma, h_s); c = preintegrated_cell(grid, preintegrated_uv(wi, wr))
//   for p = terms - 1 .. 0: acc = preintegrated_horner_step(acc, g.w - w_c, c, T_p at the 4 corners)
//   rgb = preintegrated_linear_srgb(g, acc, sigma, R0)
#ifndef FACET_DIFFRACTION_PREINTEGRATED_GLSL
#define FACET_DIFFRACTION_PREINTEGRATED_GLSL
#include "lib/prelude.glsl"
#include "lib/diffraction_brdf.glsl"
#include "lib/spectral_srgb.glsl"

// The (u, v) nodes of the tables: node (iu, iv) sits at origin + (iu, iv) * spacing. Each node holds
// `terms` coefficients T_p, p = 0..terms-1, of `words` 32-bit words each (2: XYZ as halves, 3: floats).
struct PreintegratedGrid {
  real2 origin;
  real2 spacing;
  int nu;  // nodes along u, >= 2
  int nv;  // nodes along v, >= 2
  int terms;
  int words;
};

// The cell holding (u, v): its lower-left node and the bilinear fractions. Outside the domain the
// position is clamped to its edge (the domain is built to cover every direction pair of the scene).
struct PreintegratedCell {
  int iu;
  int iv;
  real2 f;
};

inline real2 preintegrated_uv(real3 wi, real3 wr) { return -real2(wi.x + wr.x, wi.y + wr.y); }

inline PreintegratedCell preintegrated_cell(PreintegratedGrid grid, real2 uv) {
  real2 last = real2(real(grid.nu - 1), real(grid.nv - 1));
  real2 t = clamp((uv - grid.origin) / grid.spacing, real2(real(0), real(0)), last);
  int iu = min(int(floor(t.x)), grid.nu - 2);
  int iv = min(int(floor(t.y)), grid.nv - 2);
  return PreintegratedCell(iu, iv, t - real2(real(iu), real(iv)));
}

// First word of coefficient p at corner (du, dv) in {0, 1}^2 of the cell: node-major, so the
// coefficients of one node are one contiguous run.
inline int preintegrated_word_index(PreintegratedGrid grid, PreintegratedCell c, int du, int dv, int p) {
  return (((c.iv + dv) * grid.nu + c.iu + du) * grid.terms + p) * grid.words;
}

// Halves (X, Y) in `xy` and Z in the low half of `z0`, each scaled by the table's largest |T_p|.
inline real3 preintegrated_unpack_half(uint xy, uint z0, real scale) {
  real2 a = real2(unpackHalf2x16(xy));
  return real3(a.x, a.y, real(unpackHalf2x16(z0).x)) * scale;
}

inline real3 preintegrated_unpack_float(uint x, uint y, uint z, real scale) {
  return real3(real(uintBitsToFloat(x)), real(uintBitsToFloat(y)), real(uintBitsToFloat(z))) * scale;
}

// One Horner step of sum_p delta^p T_p, p descending, on the bilinearly interpolated coefficient.
inline real3 preintegrated_horner_step(real3 acc, real delta, PreintegratedCell c, real3 t00, real3 t10, real3 t01,
                                       real3 t11) {
  return acc * delta + mix(mix(t00, t10, c.f.x), mix(t01, t11, c.f.x), c.f.y);
}

// Eq. F.5: the lambda-independent factor of B.12 times the interpolated polynomial (XYZ, which
// already carries k^2 and the observer), to linear sRGB. g is diffraction_geometry at the tables'
// floor wavelength, so w, cos_i and cos_r are floored as the per-wavelength path floors them there.
inline real3 preintegrated_linear_srgb(DiffractionGeometry g, real3 poly_xyz, real sigma_nm, real R0) {
  real s = sigma_nm * g.one_plus_cos / g.w_resolved;
  real factor = diffraction_schlick_reflectance(g, R0) * s * s * FACET_INV_PI / (g.cos_i * g.cos_r);
  return spectral_xyz_to_linear_srgb(factor * poly_xyz);
}

#endif
