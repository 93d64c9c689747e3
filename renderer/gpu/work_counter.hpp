// Counts a shader's work per invocation, in code: a SPIR-V pass adds, at the start of every basic
// block, the block's float arithmetic in FMA-equivalents and its texel fetches to two private
// counters the shader declares (`facet_work_fma`, `facet_work_reads`, uint). What the shader then
// does with them is its own business (render/direct_pass.glsl writes them instead of the colour when
// kCountsWork is set). The module is otherwise unchanged, so the counts are of the same code that
// renders (docs/render_speed.md, "Work per pixel", has the weights and what they leave out).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace facet::gpu {

// The module with the counters' increments; throws facet::Error if it is not SPIR-V or does not
// declare both counters.
std::vector<uint32_t> instrument_work_counts(std::span<const uint32_t> spirv);

}  // namespace facet::gpu
