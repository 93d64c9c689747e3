// The pre-integrated diffraction colour from its tables (lib/diffraction_preintegrated.glsl; the C++
// twin is evaluate_preintegrated in renderer/diffraction/preintegrated_tables.cpp). The includer
// defines `uint diffraction_preintegrated_word(uint cell_word, uint i)` (the tables' packed word i,
// read where the cell whose first word is cell_word lies whole) and
// `float diffraction_preintegrated_scale(uint)` (one scale per polynomial coefficient).
#ifndef FACET_RENDER_DIFFRACTION_PREINTEGRATED_GLSL
#define FACET_RENDER_DIFFRACTION_PREINTEGRATED_GLSL
#include "lib/diffraction_preintegrated.glsl"

// Where one material's tables live and what the kernel needs besides the grid.
struct PreintegratedSource {
  PreintegratedGrid grid;
  uint first_word;   // of the material's table among the words
  uint first_scale;  // of its terms scales among the scales
  float w_centre;
  float floor_lambda_nm;
  float sigma_nm;
  float hs_nm;
  float R0;
};

// Coefficient p at corner (du, dv) of cell c, scaled: the words of the cell whose first word is `cell`.
// Few call sites: NIR inlines each (four corners per term), and lavapipe's pipeline set-up grows with
// them (docs/diffraction_fast_paths.md, "Warm wall clock").
vec3 diffraction_preintegrated_corner(PreintegratedSource s, PreintegratedCell c, uint cell, int du, int dv, int p,
                                      float scale) {
  uint k = s.first_word + uint(preintegrated_word_index(s.grid, c, du, dv, p));
  uint x = diffraction_preintegrated_word(cell, k), y = diffraction_preintegrated_word(cell, k + 1u);
  return s.grid.words == 2 ? preintegrated_unpack_half(x, y, scale)
                           : preintegrated_unpack_float(x, y, diffraction_preintegrated_word(cell, k + 2u), scale);
}

// Linear sRGB for wi, wr (unit vectors toward the light and the viewer in the grating's frame, z >= 0).
vec3 diffraction_preintegrated_rgb(PreintegratedSource s, vec3 wi, vec3 wr) {
  DiffractionGeometry g = diffraction_geometry(wi, wr, s.floor_lambda_nm, s.sigma_nm, s.hs_nm);
  PreintegratedCell c = preintegrated_cell(s.grid, preintegrated_uv(wi, wr));
  uint cell = s.first_word + uint(preintegrated_word_index(s.grid, c, 0, 0, 0));
  float delta = g.w - s.w_centre;
  vec3 acc = vec3(0.0);
  for (int p = s.grid.terms - 1; p >= 0; --p) {
    float scale = diffraction_preintegrated_scale(s.first_scale + uint(p));
    acc = preintegrated_horner_step(acc, delta, c, diffraction_preintegrated_corner(s, c, cell, 0, 0, p, scale),
                                    diffraction_preintegrated_corner(s, c, cell, 1, 0, p, scale),
                                    diffraction_preintegrated_corner(s, c, cell, 0, 1, p, scale),
                                    diffraction_preintegrated_corner(s, c, cell, 1, 1, p, scale));
  }
  return preintegrated_linear_srgb(g, acc, s.sigma_nm, s.R0);
}

#endif
