// C++ view of shaders/layout/diffraction_layout.glsl: the same structs, with GLM types, and how a
// grating's spectral tables fill the table record.
#pragma once

#include <glm/glm.hpp>

#include "diffraction/spectral_tables.hpp"

namespace facet::gpu {
using glm::ivec4;
using glm::uvec4;
using glm::vec4;
#include "layout/diffraction_layout.glsl"

static_assert(sizeof(DiffractionTableInfo) == 32);
static_assert(sizeof(GpuDiffractionMaterial) == 176);

inline DiffractionTableInfo table_info(const diffraction::SpectralTables& t) {
  return {ivec4(t.J, t.N, t.r, t.stored_terms), vec4(t.period_nm, t.sigma_nm, t.hs_nm, t.R0)};
}
}  // namespace facet::gpu
