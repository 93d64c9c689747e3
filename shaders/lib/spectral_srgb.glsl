// CIE 1931 XYZ -> linear sRGB (IEC 61966-2-1 primaries, D65 white). The matrix is the exact
// inverse of the one built from the primaries' and white's xy chromaticities (computed in rational
// arithmetic, docs/diffraction.md), so Y = 1 of D65 maps to (1, 1, 1); test:
// tests/diffraction/spectral_test.cpp.
#ifndef FACET_SPECTRAL_SRGB_GLSL
#define FACET_SPECTRAL_SRGB_GLSL
#include "lib/prelude.glsl"

inline real3 spectral_xyz_to_linear_srgb(real3 xyz) {
  return real3(dot(real3(real(3.2409699419045213), real(-1.5373831775700935), real(-0.49861076029300327)), xyz),
               dot(real3(real(-0.96924363628087984), real(1.8759675015077206), real(0.041555057407175612)), xyz),
               dot(real3(real(0.055630079696993608), real(-0.20397695888897657), real(1.0569715142428786)), xyz));
}

#endif
