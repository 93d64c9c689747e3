// The spectral tables of one grating as the diffraction eval shader reads them, shared by GLSL and
// C++ (renderer/diffraction/diffraction_gpu.hpp). vec4-only, so std430 equals the C++ layout.
// The coefficients themselves are a vec2 array indexed by lib/diffraction_table.glsl.
#ifndef FACET_DIFFRACTION_LAYOUT_GLSL
#define FACET_DIFFRACTION_LAYOUT_GLSL

struct DiffractionTableInfo {
  ivec4 shape;  // J (largest stored |bin|), N (Taylor terms used), r (window radius in bins), terms stored per bin
  vec4 scales;  // T (patch period, nm), sigma (coherence, nm), h_s (height unit, nm), R0
};

#endif
