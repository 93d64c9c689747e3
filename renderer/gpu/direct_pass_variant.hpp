// The variants of the direct pass's program (shaders/CMakeLists.txt): each compiles in only some
// of the code, FACET_CODE_* of shaders/layout/render_layout.glsl (material families, primitive kinds,
// the filtered methods), since lavapipe's pipeline set-up grows with the program's size whether a
// specialization constant makes the code dead or not (docs/render_speed.md, "Pipeline set-up").
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "gpu/render_method.hpp"
#include "scene/scene.hpp"

namespace facet::gpu {

struct DirectPassVariant {
  std::string_view name;  // the embedded array's, e.g. "render_direct_texture_filtered_spv"
  std::span<const uint32_t> spirv;
  uint32_t code;       // the FACET_CODE_* it compiles in
  bool height_fields;  // a variant of render_direct_fields.comp (traces microsurfaces' height fields)
};

// Every embedded variant, in the order shaders/CMakeLists.txt lists them.
std::span<const DirectPassVariant> direct_pass_variants();

// The code that rendering `scene` by `method` runs: its material families and primitive kinds, the
// filtered methods' where the scene has textures or microsurfaces, and its diffraction method's.
// orders_fall_back: under `orders`, some grating's orders are not restricted (F.10, F.11 of
// docs/diffraction_fast_paths.md), so the spectral path renders it; the diffraction's plan knows
// (gpu::orders_fall_back), the scene alone does not.
uint32_t direct_pass_code(const Scene& scene, const RenderMethod& method, bool orders_fall_back = true);

// naive, ss:K and filtered trace microsurfaces' height fields; mip and colormip shade the flat rectangle.
bool traces_height_fields(const Scene& scene, const RenderMethod& method);

// The smallest variant (in SPIR-V words) of the program `height_fields` selects that compiles in all of `code`.
const DirectPassVariant& direct_pass_variant(uint32_t code, bool height_fields);

// The variant that renders `scene` by `method`.
const DirectPassVariant& direct_pass_variant(const Scene& scene, const RenderMethod& method,
                                             bool orders_fall_back = true);

}  // namespace facet::gpu
