#include "gpu/preintegrated_slices.hpp"

#include <algorithm>
#include <string>

#include "common/error.hpp"
#include "common/format_mib.hpp"
#include "gpu/render_layout.hpp"
#include "vk/memory_limits.hpp"

namespace facet::gpu {

std::uint64_t preintegrated_cell_words(int nu, int terms, int words) {
  return (static_cast<std::uint64_t>(nu) + 2) * terms * words;
}

PreintegratedSlices slice_preintegrated_words(std::uint64_t words, std::uint64_t overlap_words,
                                              std::uint64_t binding_words) {
  PreintegratedSlices s;
  if (words <= binding_words) {
    s.ranges.emplace_back(0, words);
    return s;
  }
  const std::uint64_t slice = binding_words > overlap_words ? binding_words - overlap_words : 0;
  const std::uint64_t count = slice > 0 ? (words + slice - 1) / slice : UINT64_MAX;
  if (count > FACET_RENDER_PREINTEGRATED_SLICES || slice > UINT32_MAX)
    throw Error("the preintegrated tables (" + format_mib(4 * words) + ") need more than the render pass's " +
                std::to_string(FACET_RENDER_PREINTEGRATED_SLICES) + " texel bindings of " +
                format_mib(4 * binding_words) + " each (one cell row spans " + format_mib(4 * overlap_words) + ")");
  s.count = static_cast<std::uint32_t>(count);
  s.slice_words = static_cast<std::uint32_t>(slice);
  for (std::uint64_t j = 0; j < count; ++j)
    s.ranges.emplace_back(j * slice, std::min(words, j * slice + binding_words));
  return s;
}

std::uint64_t preintegrated_binding_words(const vk::Context& context, std::uint64_t cap_bytes) {
  std::uint64_t words = std::min<std::uint64_t>(context.limits().maxTexelBufferElements,
                                                vk::memory_limits(context.physical_device()).allocation_bytes / 4);
  if (cap_bytes > 0) words = std::min(words, cap_bytes / 4);
  return words;
}

}  // namespace facet::gpu
