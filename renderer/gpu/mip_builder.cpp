#include "gpu/mip_builder.hpp"

#include <array>

#include "build_mips.spv.h"
#include "common/error.hpp"
#include "gpu/contiguous_ids.hpp"

namespace facet::gpu {

namespace {
using glm::uvec3;
#include "layout/mip_layout.glsl"
static_assert(sizeof(GpuMipStep) == 48);
static_assert(contiguous_ids(std::array<int, FACET_MIP_BINDING_COUNT>{FACET_MIP_BINDING_TEXELS}));
}  // namespace

std::vector<glm::uvec2> mip_chain_sizes(int width, int height) {
  if (width < 1 || height < 1) throw Error("MIP chain: the level-0 size must be positive");
  std::vector<glm::uvec2> sizes{{width, height}};
  while (sizes.back().x > 1 || sizes.back().y > 1) sizes.push_back((sizes.back() + 1u) / 2u);
  return sizes;
}

MipBuilder::MipBuilder(vk::Context& context)
    : kernel_(context, {.name = "build_mips",
                        .spirv = build_mips_spv,
                        .buffer_count = FACET_MIP_BINDING_COUNT,
                        .push_constant_bytes = sizeof(GpuMipStep),
                        .image_count = 0,
                        .specialization = {},
                        .buffer_kinds = {vk::BufferKind::StorageTexels}}) {}

double MipBuilder::build(const vk::Buffer& texels, std::span<const GpuTextureLevel> chain, MipLayout layout) {
  std::array<const vk::Buffer*, FACET_MIP_BINDING_COUNT> bindings{};
  bindings[FACET_MIP_BINDING_TEXELS] = &texels;
  double gpu_ms = 0.0;
  const uvec4 base =
      chain.empty() ? uvec4(0) : uvec4(chain[0].info.y, chain[0].info.z, layout == MipLayout::Pairs ? 1u : 0u, 0);
  for (size_t l = 0; l + 1 < chain.size(); ++l) {
    const uvec4 child = chain[l].info, parent = chain[l + 1].info;
    const GpuMipStep step{uvec4(child.x, child.y, child.z, 1u << l), uvec4(parent.x, parent.y, parent.z, 0), base};
    const uvec3 groups((parent.y + FACET_MIP_WORKGROUP - 1) / FACET_MIP_WORKGROUP,
                       (parent.z + FACET_MIP_WORKGROUP - 1) / FACET_MIP_WORKGROUP, 1);
    gpu_ms += kernel_.dispatch(bindings, &step, groups);
  }
  return gpu_ms;
}

}  // namespace facet::gpu
