// The spectral tables of one grating as the diffraction shaders read them, shared by GLSL and
// C++ (renderer/gpu/diffraction_layout.hpp). vec4-only, so std430 equals the C++ layout. The
// coefficients themselves are a vec2 array indexed by lib/diffraction_table.glsl.
#ifndef FACET_DIFFRACTION_LAYOUT_GLSL
#define FACET_DIFFRACTION_LAYOUT_GLSL

struct DiffractionTableInfo {
  ivec4 shape;  // J (largest stored |bin|), N (Taylor terms used), r (window radius in bins), terms stored per bin
  vec4 scales;  // T (patch period, nm), sigma (coherence, nm), h_s (height unit, nm), R0
};

// One diffraction material of a scene in the render pass (render/diffraction_shading.glsl): its
// tables start at diffraction_coefficients[offsets.x], its wavelength samples (lambda, XYZ weight)
// are diffraction_wavelengths[offsets.y .. offsets.y + offsets.z).
// The fast paths (docs/diffraction_fast_paths.md, "Rendering") read the rest: `preintegrated` the
// grid of its tables in diffraction_preintegrated_words / _scales, `orders` the
// grating's lattice of orders and its 1 nm observer table in diffraction_observer.
struct GpuDiffractionMaterial {
  DiffractionTableInfo table;
  uvec4 offsets;  // first coefficient, first wavelength sample, wavelength count, -
  vec4 preintegrated_grid;     // origin.uv, spacing.uv
  ivec4 preintegrated_shape;   // nu, nv, terms (2N - 1), words per value (2 halves, 3 floats)
  vec4 preintegrated_scalars;  // w_centre, floor lambda (nm), sigma (nm), h_s (nm)
  uvec4 fast_offsets;          // first table word, first term scale, first observer entry, observer entries
  vec4 order_lattice0;         // frequency.xy (1/nm), sigma (nm), reach (1/nm)
  vec4 order_lattice1;         // k_min, k_max, peak_step, max_step (nm)
  vec4 fast_scalars;           // R0 of the tables, observer lambda0 (nm), 1 if periodic (orders usable), pixel reach (1/nm)
  ivec4 order_repeats;         // the lattice's repeats (P_x, P_y), nodes of a pixel's orders at most over it, -
};

#endif
