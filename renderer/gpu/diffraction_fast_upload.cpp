#include "gpu/diffraction_fast_upload.hpp"

#include <algorithm>
#include <string>
#include <variant>

#include "common/error.hpp"
#include "diffraction/order_wavelengths.hpp"
#include "diffraction/preintegrated_tables.hpp"
#include "gpu/diffraction_domain.hpp"
#include "gpu/diffraction_upload.hpp"
#include "gpu/preintegrated_slices.hpp"

namespace facet::gpu {

using diffraction::DiffractionMethod;

DiffractionMethod scene_diffraction_method(const Scene& scene, const diffraction::DiffractionSettings& settings) {
  if (settings.method) return *settings.method;
  std::optional<DiffractionMethod> chosen;
  for (const Material& material : scene.materials) {
    const auto* m = std::get_if<DiffractionMaterial>(&material);
    if (!m) continue;
    if (chosen && *chosen != m->method)
      throw Error(std::string("the scene's diffraction materials ask for different methods (") +
                  diffraction::diffraction_method_name(*chosen) + ", " +
                  diffraction::diffraction_method_name(m->method) + "); pick one for all with --diffraction");
    chosen = m->method;
  }
  return chosen.value_or(DiffractionMethod::Spectral);
}

diffraction::TableCacheUse append_fast_paths(FastPathData& data, GpuDiffractionMaterial& material, const Scene& scene,
                                             std::uint32_t scene_material,
                                             const diffraction::PreparedDiffraction& prepared, DiffractionMethod method,
                                             std::uint64_t max_bytes, const std::filesystem::path& table_cache) {
  const auto& source = std::get<DiffractionMaterial>(scene.materials[scene_material]);
  diffraction::TableCacheUse use = diffraction::TableCacheUse::Off;
  if (method == DiffractionMethod::Preintegrated) {
    const std::uint64_t used = data.preintegrated_words.size() * sizeof(std::uint32_t);
    diffraction::PreintegrationSettings settings;
    settings.tolerance = kPreintegrationTolerance;
    settings.max_bytes = max_bytes > used ? max_bytes - used : 0;
    diffraction::PreintegratedTables t;
    try {
      auto cached = diffraction::cached_preintegrated_tables(table_cache, prepared.tables, prepared.samples,
                                                             diffraction_view_domain(scene, scene_material), settings);
      t = std::move(cached.tables);
      use = cached.use;
    } catch (const Error& e) {
      throw Error("diffraction material '" + scene.material_names[scene_material] + "': " + e.what());
    }
    material.preintegrated_grid = glm::vec4(glm::vec2(t.origin), glm::vec2(t.spacing));
    material.preintegrated_shape = glm::ivec4(t.nu, t.nv, t.terms, t.words);
    material.preintegrated_scalars = glm::vec4(t.w_centre, t.floor_lambda_nm, t.sigma_nm, t.hs_nm);
    material.fast_offsets.x = static_cast<std::uint32_t>(data.preintegrated_words.size());
    material.fast_offsets.y = static_cast<std::uint32_t>(data.preintegrated_scales.size());
    material.fast_scalars.x = static_cast<float>(t.R0);
    data.cell_words = std::max(data.cell_words, preintegrated_cell_words(t.nu, t.terms, t.words));
    data.preintegrated_words.insert(data.preintegrated_words.end(), t.packed.begin(), t.packed.end());
    data.preintegrated_scales.insert(data.preintegrated_scales.end(), t.scale.begin(), t.scale.end());
  }
  if (method == DiffractionMethod::Orders) {
    const diffraction::OrderWavelengths plan = diffraction::plan_order_wavelengths(
        *source.grating, prepared.tables, source.tolerance, source.illuminant, prepared.samples);
    if (!plan.restricted) return use;  // fast_scalars.z = 0: the pass runs the spectral path
    const long iterations = order_loop_iterations(plan, prepared.tables);
    if (iterations + kTraceLoopReserve > kLoopIterationLimit)
      throw Error("diffraction material '" + scene.material_names[scene_material] + "': the orders path may need " +
                  std::to_string(iterations) + " shader loop iterations per ray; lavapipe ends a pixel's loops after " +
                  std::to_string(kLoopIterationLimit) +
                  ": use --diffraction spectral or preintegrated, or a larger tolerance");
    const auto& L = plan.lattice;
    material.order_lattice0 = glm::vec4(glm::vec2(L.frequency), L.sigma_nm, L.reach);
    material.order_lattice1 = glm::vec4(L.k_min, L.k_max, L.peak_step, L.max_step);
    material.order_repeats = glm::ivec4(L.repeats, 0, 0);
    material.fast_offsets.z = static_cast<std::uint32_t>(data.observer.size());
    material.fast_offsets.w = static_cast<std::uint32_t>(plan.observer.size());
    material.fast_scalars.y = static_cast<float>(plan.lambda0_nm);
    material.fast_scalars.z = 1.0f;
    for (const glm::dvec3& o : plan.observer) data.observer.emplace_back(glm::vec3(o), 0.0f);
  }
  return use;
}

}  // namespace facet::gpu
