// The order in which a dispatch's workgroups visit the blocks of a tile
// (render/direct_pass.glsl, tile_position). Lavapipe hands each of its T threads one contiguous 1/T of a
// dispatch's workgroups (Mesa's lp_cs_tpool: iter_per_thread = count / threads, no stealing),
// so where the costly pixels gather in one part of a tile (a highlight, a band of diffraction
// orders) that thread works alone while the others idle. Workgroup g therefore renders block
// g s mod n, with s coprime to n near n / golden ratio: every contiguous run of workgroups is
// spread evenly over the whole tile (docs/render_speed.md, item 5).
#pragma once

#include <cstdint>

namespace facet::gpu {

// The largest tile, in blocks, whose products g s (g, s < n) stay within 32 bits.
constexpr std::uint32_t kMaxTileBlocks = 65535;

// s for a tile of n blocks (1 <= n <= kMaxTileBlocks): coprime to n, so g -> g s mod n is a permutation.
std::uint32_t workgroup_spread_stride(std::uint32_t blocks);

}  // namespace facet::gpu
