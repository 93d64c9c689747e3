// Stam's diffraction BRDF at one wavelength from the spectral tables: the
// window sum over the bins near k(u, v) of each bin's Taylor sum (lib/diffraction_brdf.glsl; the
// C++ twin is evaluate_taylor in renderer/diffraction/diffraction_eval.cpp). Used by the render
// pass and by eval_diffraction.comp; the includer defines `vec2 diffraction_coefficient_at(uint i)`
// (render/diffraction_bindings.glsl reads a texel buffer, the eval kernel a storage buffer).
#ifndef FACET_RENDER_DIFFRACTION_TAYLOR_GLSL
#define FACET_RENDER_DIFFRACTION_TAYLOR_GLSL
#include "layout/diffraction_layout.glsl"
#include "lib/diffraction_brdf.glsl"
#include "lib/diffraction_table.glsl"

// H_n(j) of the tables starting at coefficient `first`.
vec2 diffraction_coefficient(DiffractionTableInfo info, uint first, int n, int jx, int jy) {
  DiffractionTableEntry e = diffraction_table_entry(n, jx, jy, info.shape.x, info.shape.w);
  vec2 c = diffraction_coefficient_at(first + uint(e.index));
  return e.conjugate ? vec2(c.x, -c.y) : c;
}

// Lavapipe ends every loop of an invocation once all loops together have run 65535 iterations
// (gallivm's LP_MAX_TGSI_LOOP_ITERATIONS, shared by every loop of a shader), silently. So the
// loops here are as few as the arithmetic allows: one loop over the (2r+1)^2 bins, and the Taylor
// steps unrolled by kDiffractionTaylorUnroll. diffraction_loop_iterations
// (renderer/gpu/diffraction_upload.cpp) counts them per wavelength: 1 + bins (1 + ceil((N-1)/8)).
const int kDiffractionTaylorUnroll = 8;

#define FACET_DIFFRACTION_GUARDED_STEP(k) \
  if (n + k < N) t = diffraction_taylor_step(t, g, diffraction_coefficient(info, first, n + k, jx, jy))

DiffractionTaylor diffraction_taylor_sum(DiffractionTaylor t, DiffractionGeometry g, DiffractionTableInfo info,
                                         uint first, int jx, int jy) {
  int N = info.shape.y;
  for (int n = 1; n < N; n += kDiffractionTaylorUnroll) {  // written out: an inner loop would count
    t = diffraction_taylor_step(t, g, diffraction_coefficient(info, first, n, jx, jy));
    FACET_DIFFRACTION_GUARDED_STEP(1);
    FACET_DIFFRACTION_GUARDED_STEP(2);
    FACET_DIFFRACTION_GUARDED_STEP(3);
    FACET_DIFFRACTION_GUARDED_STEP(4);
    FACET_DIFFRACTION_GUARDED_STEP(5);
    FACET_DIFFRACTION_GUARDED_STEP(6);
    FACET_DIFFRACTION_GUARDED_STEP(7);
  }
  return t;
}
#undef FACET_DIFFRACTION_GUARDED_STEP

// Bin j's Taylor sum sum_n (i x)^n / n! H_n(j) (C.1).
DiffractionTaylor diffraction_bin_taylor(DiffractionTableInfo info, uint first, DiffractionGeometry g, ivec2 j) {
  DiffractionTaylor t = diffraction_taylor_start(g, diffraction_coefficient(info, first, 0, j.x, j.y));
  return diffraction_taylor_sum(t, g, info, first, j.x, j.y);
}

// The window sum over the bins near k(u, v) (C.1), or with `one_bin` bin j's term alone with weight 1: the
// BRDF of one order whose window the caller weighs (the orders over a pixel, eq. O2 of
// docs/diffraction_fast_paths.md; C++ twins evaluate_taylor and evaluate_bin). One function for both, so the
// orders' loop, which takes either, inlines the Taylor sum once (lavapipe compiles each call site on its own).
// wi, wr: unit vectors toward the light and the viewer in the grating's frame, z >= 0. bin_stride:
// (1, 1) visits every bin of the window; a periodic patch's repeats visit only its lattice
// (lib/diffraction_brdf.glsl, diffraction_window_bins).
DiffractionValue diffraction_window_value(DiffractionTableInfo info, uint first, vec3 wi, vec3 wr, float lambda_nm,
                                          ivec2 bin_stride, bool one_bin, ivec2 j_one) {
  int J = info.shape.x;
  float T = info.scales.x, sigma = info.scales.y;
  DiffractionGeometry g = diffraction_geometry(wi, wr, lambda_nm, sigma, info.scales.z);
  DiffractionWindowBins bins = diffraction_window_bins(g.alpha, T, info.shape.z, bin_stride);
  DiffractionField field = DiffractionField(vec2(0.0), vec2(0.0));
  int count = one_bin ? 1 : bins.count.x * bins.count.y;
  for (int b = 0; b < count; ++b) {
    ivec2 j = one_bin ? j_one : diffraction_window_bin(bins, b);
    if (!diffraction_table_entry(0, j.x, j.y, J, 1).valid) continue;
    float weight = one_bin ? 1.0 : diffraction_window_weight(g.alpha - diffraction_bin_frequency(j.x, j.y, T), sigma);
    field = diffraction_field_add(field, weight, diffraction_bin_taylor(info, first, g, j));
  }
  return diffraction_value(g, field, sigma, info.scales.w);
}

DiffractionValue diffraction_taylor_value(DiffractionTableInfo info, uint first, vec3 wi, vec3 wr, float lambda_nm,
                                          ivec2 bin_stride) {
  return diffraction_window_value(info, first, wi, wr, lambda_nm, bin_stride, false, ivec2(0));
}

#endif
