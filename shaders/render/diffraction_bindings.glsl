// The diffraction buffers of the direct pass (slots FACET_RENDER_BINDING_DIFFRACTION_* of
// layout/render_layout.glsl, filled by renderer/gpu/diffraction_upload.cpp): uniform texel buffers
// like the scene's tables (render/scene_bindings.glsl), each viewed with texels as wide as its
// elements (vk::Buffer::texel_bytes). The loops over wavelengths, orders and Taylor terms read them;
// a storage buffer there costs a branch per lane and component on lavapipe 22.3.
// Defines the accessors the shared diffraction code reads through (render/diffraction_taylor.glsl,
// _orders.glsl, _preintegrated.glsl).
#ifndef FACET_RENDER_DIFFRACTION_BINDINGS_GLSL
#define FACET_RENDER_DIFFRACTION_BINDINGS_GLSL
#include "layout/diffraction_layout.glsl"
#include "render/scene_bindings.glsl"

// Coefficients RG32UI (vec2), preintegrated words and scales R32UI, the others RGBA32UI.
#define FACET_DIFFRACTION_TEXELS(slot, name) \
  layout(binding = FACET_RENDER_BINDING_DIFFRACTION_##slot) uniform usamplerBuffer name
FACET_DIFFRACTION_TEXELS(COEFFICIENTS, diffraction_coefficient_texels);
FACET_DIFFRACTION_TEXELS(MATERIALS, diffraction_material_texels);
FACET_DIFFRACTION_TEXELS(WAVELENGTHS, diffraction_wavelength_texels);
FACET_DIFFRACTION_TEXELS(PREINTEGRATED_WORDS, diffraction_word_texels);
FACET_DIFFRACTION_TEXELS(PREINTEGRATED_SCALES, diffraction_scale_texels);
FACET_DIFFRACTION_TEXELS(OBSERVER, diffraction_observer_texels);
FACET_DIFFRACTION_TEXELS(PREINTEGRATED_WORDS_1, diffraction_word_texels_1);
FACET_DIFFRACTION_TEXELS(PREINTEGRATED_WORDS_2, diffraction_word_texels_2);
FACET_DIFFRACTION_TEXELS(PREINTEGRATED_WORDS_3, diffraction_word_texels_3);
#undef FACET_DIFFRACTION_TEXELS

GpuDiffractionMaterial diffraction_material_at(uint i) {
  uint k = 11u * i;
  return GpuDiffractionMaterial(
      DiffractionTableInfo(ivec4(FACET_U(diffraction_material_texels, k)),
                           FACET_F(diffraction_material_texels, k + 1u)),
      FACET_U(diffraction_material_texels, k + 2u), FACET_F(diffraction_material_texels, k + 3u),
      ivec4(FACET_U(diffraction_material_texels, k + 4u)), FACET_F(diffraction_material_texels, k + 5u),
      FACET_U(diffraction_material_texels, k + 6u), FACET_F(diffraction_material_texels, k + 7u),
      FACET_F(diffraction_material_texels, k + 8u), FACET_F(diffraction_material_texels, k + 9u),
      ivec4(FACET_U(diffraction_material_texels, k + 10u)));
}

vec4 diffraction_wavelength_at(uint i) { return FACET_F(diffraction_wavelength_texels, i); }  // lambda, XYZ
vec2 diffraction_coefficient_at(uint i) { return FACET_F(diffraction_coefficient_texels, i).xy; }
vec4 diffraction_observer_at(uint i) { return FACET_F(diffraction_observer_texels, i); }  // XYZ per nm

// Word i of the preintegrated tables, from the slice holding every word of the cell whose first word
// is cell_word: slice j binds words [j S, j S + S + overlap) and holds the cells starting in
// [j S, (j + 1) S), S = kPreintegratedSliceWords (renderer/gpu/preintegrated_slices.hpp). One
// slice (every table that fits one binding) compiles to a single fetch.
uint diffraction_preintegrated_word(uint cell_word, uint i) {
  if (kPreintegratedSlices == 1u) return FACET_U(diffraction_word_texels, i).x;
  uint slice = cell_word / kPreintegratedSliceWords;
  uint k = i - slice * kPreintegratedSliceWords;
  if (slice == 0u) return FACET_U(diffraction_word_texels, k).x;
  if (slice == 1u) return FACET_U(diffraction_word_texels_1, k).x;
  if (slice == 2u) return FACET_U(diffraction_word_texels_2, k).x;
  return FACET_U(diffraction_word_texels_3, k).x;
}
float diffraction_preintegrated_scale(uint i) { return FACET_F(diffraction_scale_texels, i).x; }

#endif
