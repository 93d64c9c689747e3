// Compile-time check of a named binding contract: the names' values must be first..first+N-1, each
// once, as vk::Kernel's descriptor-set layout (slots 0..B-1) and a specialization map assume; two
// names on one slot would otherwise bind one buffer where the shader reads another.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

namespace facet::gpu {

template <std::size_t N>
constexpr bool contiguous_ids(std::array<int, N> ids, int first = 0) {
  std::ranges::sort(ids);
  for (std::size_t i = 0; i < N; ++i)
    if (ids[i] != first + static_cast<int>(i)) return false;
  return true;
}

}  // namespace facet::gpu
