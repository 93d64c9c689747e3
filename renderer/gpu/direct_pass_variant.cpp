#include "gpu/direct_pass_variant.hpp"

#include <array>
#include <variant>

#include "common/error.hpp"
#include "gpu/diffraction_fast_upload.hpp"
#include "gpu/render_layout.hpp"
#include "render_direct_variants.hpp"

namespace facet::gpu {

namespace {

// Every bit of FACET_CODE_ALL names code (shaders/layout/render_layout.glsl).
static_assert(FACET_CODE_ALL ==
              (FACET_CODE_TEXTURE | FACET_CODE_DIFFRACTION | FACET_CODE_MICROFLAKE | FACET_CODE_MICROSURFACE |
               FACET_CODE_SPHERES | FACET_CODE_TRIANGLES | FACET_CODE_FILTERED | FACET_CODE_DIFFRACTION_PREINTEGRATED |
               FACET_CODE_DIFFRACTION_ORDERS | FACET_CODE_DIFFRACTION_SPECTRAL));

#define FACET_DIRECT_PASS_VARIANT(array, source, code) \
  DirectPassVariant{#array, array, code, std::string_view(#source) == "render_direct_fields"},
const auto kVariants = std::to_array<DirectPassVariant>({FACET_SHADER_VARIANTS(FACET_DIRECT_PASS_VARIANT)});
#undef FACET_DIRECT_PASS_VARIANT

template <class M>
bool uses(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (std::holds_alternative<M>(m)) return true;
  return false;
}

}  // namespace

std::span<const DirectPassVariant> direct_pass_variants() { return kVariants; }

uint32_t direct_pass_code(const Scene& scene, const RenderMethod& method, bool orders_fall_back) {
  uint32_t code = 0;
  if (uses<ColormapTextureMaterial>(scene)) code |= FACET_CODE_TEXTURE;
  if (uses<DiffractionMaterial>(scene)) code |= FACET_CODE_DIFFRACTION;
  if (uses<MicroflakeMaterial>(scene)) code |= FACET_CODE_MICROFLAKE;
  if (uses<MicrosurfaceMaterial>(scene)) code |= FACET_CODE_MICROSURFACE;
  if (!scene.spheres.empty()) code |= FACET_CODE_SPHERES;
  if (!scene.meshes.empty()) code |= FACET_CODE_TRIANGLES;
  if ((code & FACET_CODE_DIFFRACTION) != 0) {
    const diffraction::DiffractionMethod diffraction = scene_diffraction_method(scene, method.diffraction);
    if (diffraction == diffraction::DiffractionMethod::Preintegrated) code |= FACET_CODE_DIFFRACTION_PREINTEGRATED;
    if (diffraction == diffraction::DiffractionMethod::Orders) code |= FACET_CODE_DIFFRACTION_ORDERS;
    // `orders` runs the spectral path where restricting does not pay (F.10, F.11).
    if (diffraction == diffraction::DiffractionMethod::Spectral ||
        (diffraction == diffraction::DiffractionMethod::Orders && orders_fall_back))
      code |= FACET_CODE_DIFFRACTION_SPECTRAL;
  }
  // The filtered methods' code: textures' footprints, microsurfaces' statistics, microflake lobes and
  // `orders` over the pixel.
  constexpr uint32_t kFilterable =
      FACET_CODE_TEXTURE | FACET_CODE_MICROSURFACE | FACET_CODE_MICROFLAKE | FACET_CODE_DIFFRACTION_ORDERS;
  if (method.filters() && (code & kFilterable) != 0) code |= FACET_CODE_FILTERED;
  return code;
}

bool traces_height_fields(const Scene& scene, const RenderMethod& method) {
  return uses<MicrosurfaceMaterial>(scene) && method.texture != RenderMethod::Texture::Mip &&
         method.texture != RenderMethod::Texture::Colormip;
}

const DirectPassVariant& direct_pass_variant(uint32_t code, bool height_fields) {
  const DirectPassVariant* best = nullptr;
  for (const DirectPassVariant& v : kVariants)
    if (v.height_fields == height_fields && (v.code & code) == code && (!best || v.spirv.size() < best->spirv.size()))
      best = &v;
  if (!best) throw Error("no variant of the direct pass compiles in code " + std::to_string(code));
  return *best;
}

const DirectPassVariant& direct_pass_variant(const Scene& scene, const RenderMethod& method, bool orders_fall_back) {
  return direct_pass_variant(direct_pass_code(scene, method, orders_fall_back), traces_height_fields(scene, method));
}

}  // namespace facet::gpu
