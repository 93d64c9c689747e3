// The colour-mapped textures of a scene as GPU data: per texture a MIP chain of moments
// (E[t], E[t^2], within-texel variance) and a MIP chain of the colour-mapped texture (for the
// `colormip` baseline), level 0 computed on the CPU and the coarser levels box-filtered on the GPU
// (gpu/mip_builder.hpp); the colour maps as control points and, for `filtered:table`, their
// prefiltered tables (layouts in shaders/layout/scene_layout.glsl).
#pragma once

#include <span>
#include <vector>

#include "gpu/mip_builder.hpp"
#include "gpu/scene_layout.hpp"
#include "gpu/texel_store.hpp"
#include "precompute/prefiltered_colormap.hpp"
#include "scene/scene.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

// A chain for build_gpu_mips to fill: its first level record, its level count and how it keeps its texels.
struct GpuMipChain {
  uint first = 0;
  uint levels = 0;
  MipLayout layout = MipLayout::Texels;
};

struct TextureData {
  std::vector<GpuTextureLevel> levels;
  TexelStore texels;
  std::vector<GpuColormap> colormaps;
  std::vector<vec4> colormap_points;   // linear rgb, position
  std::vector<GpuMipChain> gpu_chains;  // filled by build_gpu_mips
};

// The texels of a MIP chain over width x height: its levels' (mip_chain_sizes) in all.
std::size_t mip_chain_texels(int width, int height);

// Appends a MIP chain of vec4 texels laid out as `layout`: room for level 0 (width * height texels,
// row-major, for the caller to fill through level_texels) and the coarser levels (mip_chain_sizes),
// which build_gpu_mips box-filters. Level records hold (offset, width, height, index in the chain), as
// texel_quad (render/texture_sampling.glsl) reads them. Returns the index of its first level record.
uint append_mip_chain(TextureData& data, int width, int height, MipLayout layout = MipLayout::Texels);

// The texels of level record `level` (width * height of them, row-major).
std::span<vec4> level_texels(TextureData& data, uint level);

// Builds every chain of data.gpu_chains in `texels`, the uploaded data.texels. Returns the GPU ms.
double build_gpu_mips(vk::Context& context, const vk::Buffer& texels, const TextureData& data);

// Per colour channel: about one 8-bit step.
constexpr double kColormapTableTolerance = 4e-3;

// A step map's table meets the tolerance only above a sigma floor (bilinear interpolation cannot
// follow a jump as sigma -> 0): 1% of its control-point span, in texture values. 0 for linear maps.
double colormap_table_sigma_floor(const Colormap& map);

// The prefiltered table of a material's colour map as `filtered:table` uses it: kColormapTableTolerance,
// sigma up to half the texture's value range (no footprint's standard deviation can exceed it) and
// colormap_table_sigma_floor.
precompute::PrefilteredColormap build_colormap_table(const ColormapTextureMaterial& material);

// Whether the GPU finds a segment of `map` from a division (evenly spaced, and more than 4 points, below which the
// bisection alone takes at most 2 trips): GpuColormap.info.w, kColormapDivides (render/texture_sampling.glsl).
bool colormap_searched_by_division(const Colormap& map);

// Appends the control points of `map` to data.colormap_points; returns its record (no table), for
// the caller to complete and push to data.colormaps.
GpuColormap append_colormap_points(TextureData& data, const Colormap& map);

// Appends the MIP chains of `material` and its colour map (with its prefiltered table when
// `with_table`); returns the GpuMaterial::texture field (first moment level, level count, first
// colour-MIP level, colour map index). The moments are a chain of pairs (MipLayout::Pairs) of
// (E[t], E[t^2] + within-texel variance): the two a lookup needs (docs/colormap_filtering.md,
// "Footprint variance"), each a box mean over the covered level-0 texels.
uvec4 add_colormap_texture(TextureData& data, const ColormapTextureMaterial& material, bool with_table = false);

// The texels add_colormap_texture appends without a table (the two chains), so that the upload can
// reserve them before it builds them.
std::size_t colormap_texture_texels(const ColormapTextureMaterial& material);

}  // namespace facet::gpu
