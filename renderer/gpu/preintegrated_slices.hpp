// The `preintegrated` tables' words over the direct pass's FACET_RENDER_PREINTEGRATED_SLICES word
// bindings (layout/render_layout.glsl). One R32UI texel binding holds maxTexelBufferElements words
// (lavapipe: 512 MiB), less than a wide view's tables may take (the showcase's crossed grating:
// 1058 MiB). The words are cut into slices of S words; binding j holds slice j and the `overlap`
// words after it, so every word of a cell whose first word lies in slice j is in binding j. The
// shader thus picks one binding per cell (render/diffraction_bindings.glsl) and the tables keep one
// array and one addressing, where tiling the (u, v) domain would add a second.
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "vk/context.hpp"

namespace facet::gpu {

struct PreintegratedSlices {
  std::uint32_t count = 1;                 // bindings used
  std::uint32_t slice_words = UINT32_MAX;  // S: cells whose first word is in [j S, (j + 1) S) read binding j
  std::vector<std::pair<std::size_t, std::size_t>> ranges;  // per binding, its [begin, end) words
};

// The words one cell of a table with nu nodes per row spans, from the first word of its lower-left
// node to the last of its upper-right one (preintegrated_word_index): the overlap the slices need.
std::uint64_t preintegrated_cell_words(int nu, int terms, int words);

// Slices `words` words over bindings of at most binding_words each. Throws facet::Error (one line,
// with the sizes) when FACET_RENDER_PREINTEGRATED_SLICES bindings cannot hold them.
PreintegratedSlices slice_preintegrated_words(std::uint64_t words, std::uint64_t overlap_words,
                                              std::uint64_t binding_words);

// The words one binding may hold on this device: maxTexelBufferElements R32UI texels within one
// allocation (maxMemoryAllocationSize), or cap_bytes / 4 when that is lower and nonzero (tests split
// small tables with it).
std::uint64_t preintegrated_binding_words(const vk::Context& context, std::uint64_t cap_bytes);

}  // namespace facet::gpu
