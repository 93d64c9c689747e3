// Box-filtered MIP chains of vec4 texels built on the GPU (shaders/build_mips.comp), in place in a
// texel buffer whose level 0 is already uploaded. The CPU reference is precompute::build_moment_mips
// (same sizes, same weights; tests/gpu/mip_builder_test.cpp compares them).
#pragma once

#include <span>
#include <vector>

#include "gpu/scene_layout.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/kernel.hpp"

namespace facet::gpu {

// How a chain keeps its texels. Texels: one vec4 texel per texel. Pairs: two channels (a, b) per texel,
// each vec4 holding them for its texel and for the next one of its row, the first after the last:
// (a_i, b_i, a_i+1, b_i+1), so that a bilinear lookup, which reads texels i and i + 1 of two rows
// (lib/mip_grid.glsl), makes two loads instead of four (render/texture_sampling.glsl).
enum class MipLayout { Texels, Pairs };

// The level sizes of a chain from width x height down to 1x1: size_{l+1} = ceil(size_l / 2).
std::vector<glm::uvec2> mip_chain_sizes(int width, int height);

class MipBuilder {
 public:
  explicit MipBuilder(vk::Context& context);

  // Fills levels 1.. of `chain` (records of one chain, level 0 first, offsets in vec4 texels of
  // `texels`, laid out as `layout`) from level 0, one dispatch per level. Returns the summed GPU time
  // in milliseconds.
  double build(const vk::Buffer& texels, std::span<const GpuTextureLevel> chain, MipLayout layout);

 private:
  vk::Kernel kernel_;
};

}  // namespace facet::gpu
