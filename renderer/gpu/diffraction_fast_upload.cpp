#include "gpu/diffraction_fast_upload.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "common/error.hpp"
#include "diffraction/order_wavelengths.hpp"
#include "diffraction/preintegrated_cache.hpp"
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

void append_fast_paths(FastPathData& data, GpuDiffractionMaterial& material, const Scene& scene,
                       std::uint32_t scene_material, const diffraction::PreparedDiffraction& prepared,
                       DiffractionMethod method, bool over_pixel, std::uint64_t max_bytes) {
  const auto& source = std::get<DiffractionMaterial>(scene.materials[scene_material]);
  if (method == DiffractionMethod::Preintegrated) {
    const std::uint64_t used = data.preintegrated_word_count * sizeof(std::uint32_t);
    PendingTables pending{
        scene.material_names[scene_material], &prepared, diffraction_view_domain(scene, scene_material), {}, {},
        data.preintegrated_word_count};
    pending.settings.tolerance = kPreintegrationTolerance;
    pending.settings.max_bytes = max_bytes > used ? max_bytes - used : 0;
    try {
      pending.header =
          diffraction::preintegrated_header(prepared.tables, prepared.samples, pending.domain, pending.settings);
    } catch (const Error& e) {
      throw Error("diffraction material '" + pending.material + "': " + e.what());
    }
    const diffraction::PreintegratedTables& t = pending.header;
    material.preintegrated_grid = glm::vec4(glm::vec2(t.origin), glm::vec2(t.spacing));
    material.preintegrated_shape = glm::ivec4(t.nu, t.nv, t.terms, t.words);
    material.preintegrated_scalars = glm::vec4(t.w_centre, t.floor_lambda_nm, t.sigma_nm, t.hs_nm);
    material.fast_offsets.x = static_cast<std::uint32_t>(data.preintegrated_word_count);
    material.fast_offsets.y = static_cast<std::uint32_t>(data.preintegrated_scales.size());
    material.fast_scalars.x = static_cast<float>(t.R0);
    data.cell_words = std::max(data.cell_words, preintegrated_cell_words(t.nu, t.terms, t.words));
    data.preintegrated_word_count += t.word_count();
    data.preintegrated_scales.resize(data.preintegrated_scales.size() + t.terms);
    data.preintegrated.push_back(std::move(pending));
  }
  if (method == DiffractionMethod::Orders) {
    const diffraction::OrderWavelengths plan = diffraction::plan_order_wavelengths(
        *source.grating, prepared.tables, source.tolerance, source.illuminant, prepared.samples);
    if (!plan.restricted) return;  // fast_scalars.z = 0: the pass runs the spectral path
    const long iterations = order_loop_iterations(plan, prepared.tables, over_pixel);
    if (iterations + kTraceLoopReserve > kLoopIterationLimit)
      throw Error("diffraction material '" + scene.material_names[scene_material] + "': the orders path may need " +
                  std::to_string(iterations) + " shader loop iterations per ray; lavapipe ends a pixel's loops after " +
                  std::to_string(kLoopIterationLimit) + ": use --diffraction spectral or preintegrated" +
                  (over_pixel ? ", a method that does not filter," : "") + " or a larger tolerance");
    const auto& L = plan.lattice;
    material.order_lattice0 = glm::vec4(glm::vec2(L.frequency), L.sigma_nm, L.reach);
    material.order_lattice1 = glm::vec4(L.k_min, L.k_max, L.peak_step, L.max_step);
    material.order_repeats = glm::ivec4(L.repeats, L.pixel_budget, 0);
    material.fast_scalars.w = static_cast<float>(L.pixel_reach);
    material.fast_offsets.z = static_cast<std::uint32_t>(data.observer.size());
    material.fast_offsets.w = static_cast<std::uint32_t>(plan.observer.size());
    material.fast_scalars.y = static_cast<float>(plan.lambda0_nm);
    material.fast_scalars.z = 1.0f;
    for (const glm::dvec3& o : plan.observer) data.observer.emplace_back(glm::vec3(o), 0.0f);
  }
}

namespace {

// The one material's tables bound where the cache file's mapping holds them (no copy, no allocation:
// its pages come from the page cache as the checksum reads them), when the device imports host memory
// and one binding holds the tables; nullopt otherwise, or without a cache file of them.
std::optional<vk::Buffer> import_cached_words(vk::Context& context, FastPathData& data,
                                              const PreintegratedSlices& slices,
                                              const std::filesystem::path& table_cache) {
  const VkDeviceSize alignment = context.host_import_alignment();
  if (alignment == 0 || data.preintegrated.size() != 1 || slices.ranges.size() != 1) return std::nullopt;
  PendingTables& p = data.preintegrated.front();
  std::optional<diffraction::MappedTableWords> mapped = diffraction::map_cached_preintegrated_words(
      table_cache, p.prepared->tables, p.prepared->samples, p.domain, p.settings, p.header);
  if (!mapped) return std::nullopt;
  auto* words = const_cast<std::uint32_t*>(mapped->words.data());  // copy-on-write: the device only reads
  const auto* end = reinterpret_cast<const std::byte*>(mapped->file->data()) + mapped->file->mapped_bytes();
  const VkDeviceSize bytes = mapped->words.size_bytes();
  const VkDeviceSize span = (bytes + alignment - 1) / alignment * alignment;
  if (reinterpret_cast<std::uintptr_t>(words) % alignment != 0 ||
      span > static_cast<VkDeviceSize>(end - reinterpret_cast<const std::byte*>(words)))
    return std::nullopt;
  std::copy(p.header.scale.begin(), p.header.scale.end(), data.preintegrated_scales.begin());
  return vk::Buffer::import_host(context, words, bytes, sizeof(std::uint32_t), std::move(mapped->file));
}

}  // namespace

PreintegratedWords upload_preintegrated_words(vk::Context& context, FastPathData& data,
                                              const PreintegratedSlices& slices,
                                              const std::filesystem::path& table_cache) {
  if (slices.ranges.empty() || slices.ranges.back().second != data.preintegrated_word_count)
    throw Error("internal: the preintegrated slices do not cover the tables' words");
  PreintegratedWords result{{}, slices};
  if (std::optional<vk::Buffer> imported = import_cached_words(context, data, slices, table_cache)) {
    result.buffers.push_back(std::move(*imported));
    result.use = diffraction::TableCacheUse::Hit;
    return result;
  }
  for (const auto& [begin, end] : result.slices.ranges)
    result.buffers.push_back(vk::Buffer::of<std::uint32_t>(context, end - begin));
  if (data.preintegrated.empty()) return result;
  // Where the words are read or built: the binding itself when the host sees it, else a staging buffer.
  const bool direct = result.buffers.size() == 1 && result.buffers[0].mapped();
  std::optional<vk::Buffer> staging;
  if (!direct) staging.emplace(vk::Buffer::staging(context, data.preintegrated_word_count * sizeof(std::uint32_t)));
  auto* words = static_cast<std::uint32_t*>(direct ? result.buffers[0].mapped() : staging->mapped());
  const std::uint64_t cache_bytes = table_cache.empty() ? 0 : diffraction::table_cache_max_bytes();
  std::uint64_t scale_offset = 0;
  for (PendingTables& p : data.preintegrated) {
    diffraction::TableCacheUse use;
    try {
      use = diffraction::cached_preintegrated_words(table_cache, p.prepared->tables, p.prepared->samples, p.domain,
                                                    p.settings, p.header,
                                                    {words + p.word_offset, p.header.word_count()}, cache_bytes);
    } catch (const Error& e) {
      throw Error("diffraction material '" + p.material + "': " + e.what());
    }
    std::copy(p.header.scale.begin(), p.header.scale.end(), data.preintegrated_scales.begin() + scale_offset);
    scale_offset += p.header.scale.size();
    if (use == diffraction::TableCacheUse::Miss || result.use == diffraction::TableCacheUse::Off) result.use = use;
  }
  if (staging)
    for (size_t j = 0; j < result.buffers.size(); ++j) {
      const auto& [begin, end] = result.slices.ranges[j];
      if (end > begin)
        result.buffers[j].copy_from(*staging, (end - begin) * sizeof(std::uint32_t), begin * sizeof(std::uint32_t));
    }
  return result;
}

}  // namespace facet::gpu
