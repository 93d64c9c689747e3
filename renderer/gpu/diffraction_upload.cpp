#include "gpu/diffraction_upload.hpp"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "common/error.hpp"
#include "common/format_mib.hpp"
#include "diffraction/spectral_tables.hpp"
#include "gpu/diffraction_fast_upload.hpp"
#include "gpu/diffraction_layout.hpp"
#include "gpu/render_layout.hpp"
#include "vk/memory_limits.hpp"

namespace facet::gpu {

namespace {

// One bin's loop iterations: itself plus the Taylor steps, unrolled by 8 (kDiffractionTaylorUnroll
// in render/diffraction_taylor.glsl).
long bin_loop_iterations(const diffraction::SpectralTables& tables) { return 1 + (tables.N - 1 + 7) / 8; }

}  // namespace

long diffraction_loop_iterations(const diffraction::PreparedDiffraction& prepared) {
  const long bins = (2L * prepared.tables.r + 1) * (2L * prepared.tables.r + 1);
  return static_cast<long>(prepared.samples.lambda_nm.size()) * (1 + bins * bin_loop_iterations(prepared.tables));
}

long order_loop_iterations(const diffraction::OrderWavelengths& plan, const diffraction::SpectralTables& tables,
                           bool over_pixel) {
  const auto& L = plan.lattice;
  // Over the pixel: two passes over the candidates, then at most budget + candidates nodes of one bin each (O3).
  if (kernels::f64::diffraction_orders_over_pixel(L, over_pixel)) {
    const long candidates = static_cast<long>(std::ceil(plan.worst_orders_over_pixel));
    return 2 * candidates + (L.pixel_budget + candidates) * (2 + bin_loop_iterations(tables));
  }
  const glm::dvec2 radius = glm::floor(glm::dvec2(L.reach) / L.frequency + 0.5);  // diffraction_order_share's
  const long share = static_cast<long>((2 * radius.y + 1) * (2 * radius.x + 2));  // rows, each with its columns
  const glm::ivec2 bins = 2 * tables.r / L.repeats + 1;                           // lattice bins per axis, at most
  const long per_node = 2 + share + static_cast<long>(bins.x) * bins.y * bin_loop_iterations(tables);
  return static_cast<long>(std::ceil(plan.worst_orders) + std::ceil(plan.most_nodes) * per_node);
}

DiffractionPlan plan_diffraction(const vk::Context& context, const Scene& scene,
                                 const diffraction::DiffractionSettings& settings) {
  DiffractionPlan plan;
  // The preintegrated tables may take the device's memory, or what the pass's word bindings hold if less.
  const std::uint64_t binding_words = preintegrated_binding_words(context, settings.preintegrated_binding_bytes);
  const std::uint64_t table_memory =
      std::min<std::uint64_t>(vk::memory_limits(context.physical_device()).heap_bytes,
                              sizeof(std::uint32_t) * binding_words * FACET_RENDER_PREINTEGRATED_SLICES);
  plan.method = scene_diffraction_method(scene, settings);
  plan.prepared = diffraction::prepare_scene_diffraction(scene, settings);
  for (size_t i = 0; i < plan.prepared.size(); ++i) {
    const auto& prepared = plan.prepared[i];
    if (!prepared) continue;
    const long iterations = diffraction_loop_iterations(*prepared);
    if (plan.method != diffraction::DiffractionMethod::Preintegrated &&
        iterations + kTraceLoopReserve > kLoopIterationLimit)
      throw Error("diffraction material '" + scene.material_names[i] +
                  "': " + std::to_string(prepared->samples.lambda_nm.size()) + " wavelengths x " +
                  std::to_string((2 * prepared->tables.r + 1) * (2 * prepared->tables.r + 1)) + " bins x " +
                  std::to_string(prepared->tables.N) + " Taylor terms need " + std::to_string(iterations) +
                  " shader loop iterations per ray; lavapipe ends a pixel's loops after " +
                  std::to_string(kLoopIterationLimit) + ": raise the tolerance or use fewer wavelengths");
    const std::vector<glm::vec2> table = prepared->tables.coefficients_f32();
    const diffraction::WavelengthSamples& s = prepared->samples;
    GpuDiffractionMaterial entry{};  // the fast paths' fields stay zero unless their method fills them
    entry.table = table_info(prepared->tables);
    entry.offsets = glm::uvec4(plan.coefficients.size(), plan.wavelengths.size(), s.lambda_nm.size(), 0);
    append_fast_paths(plan.fast, entry, scene, static_cast<uint32_t>(i), *prepared, plan.method, settings.over_pixel,
                      table_memory);
    plan.materials.push_back(entry);
    plan.most_wavelengths = std::max(plan.most_wavelengths, static_cast<int>(s.lambda_nm.size()));
    plan.most_taylor = std::max(plan.most_taylor, prepared->tables.N);
    plan.coefficients.insert(plan.coefficients.end(), table.begin(), table.end());
    for (size_t k = 0; k < s.lambda_nm.size(); ++k)
      plan.wavelengths.emplace_back(static_cast<float>(s.lambda_nm[k]), glm::vec3(s.xyz_weight[k]));
  }
  // The coefficients are one RG32UI texel binding (render/diffraction_bindings.glsl).
  const uint64_t bytes = plan.coefficients.size() * sizeof(glm::vec2);
  const uint64_t coefficient_limit = sizeof(glm::vec2) * static_cast<uint64_t>(context.limits().maxTexelBufferElements);
  if (bytes > coefficient_limit)
    throw Error("the spectral tables of this scene (" + format_mib(bytes) + ") exceed the device's texel buffer of " +
                format_mib(coefficient_limit) + "; use gratings with fewer samples or a larger tolerance");
  plan.preintegrated_slices =
      slice_preintegrated_words(plan.fast.preintegrated_word_count, plan.fast.cell_words, binding_words);
  return plan;
}

bool orders_fall_back(const DiffractionPlan& plan) {
  return plan.method == diffraction::DiffractionMethod::Orders &&
         std::ranges::any_of(plan.materials, [](const GpuDiffractionMaterial& m) { return m.fast_scalars.z == 0.0f; });
}

DiffractionBuffers upload_diffraction(vk::Context& context, DiffractionPlan plan) {
  FastPathData& fast = plan.fast;
  PreintegratedWords words =
      upload_preintegrated_words(context, fast, plan.preintegrated_slices, diffraction::table_cache_dir());
  // Placeholders where a method has no data (a buffer cannot be empty).
  if (fast.preintegrated_scales.empty()) fast.preintegrated_scales.push_back(0.0f);
  if (fast.observer.empty()) fast.observer.emplace_back(0.0f);
  DiffractionBuffers buffers{vk::Buffer::from(context, std::span<const glm::vec2>(plan.coefficients)),
                             vk::Buffer::from(context, std::span<const GpuDiffractionMaterial>(plan.materials)),
                             vk::Buffer::from(context, std::span<const glm::vec4>(plan.wavelengths)),
                             std::move(words.buffers),
                             std::move(words.slices),
                             vk::Buffer::from(context, std::span<const float>(fast.preintegrated_scales)),
                             vk::Buffer::from(context, std::span<const glm::vec4>(fast.observer)),
                             plan.method,
                             plan.most_wavelengths,
                             plan.most_taylor,
                             words.use};
  while (buffers.preintegrated_words.size() < FACET_RENDER_PREINTEGRATED_SLICES)
    buffers.preintegrated_words.push_back(vk::Buffer::from(context, std::span<const uint32_t>()));
  return buffers;
}

DiffractionBuffers upload_diffraction(vk::Context& context, const Scene& scene,
                                      const diffraction::DiffractionSettings& settings) {
  return upload_diffraction(context, plan_diffraction(context, scene, settings));
}

}  // namespace facet::gpu
