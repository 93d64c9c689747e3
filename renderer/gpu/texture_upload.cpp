#include "gpu/texture_upload.hpp"

#include <algorithm>
#include <array>

#include <tbb/parallel_for.h>

#include "gpu/mip_builder.hpp"
#include "precompute/moment_mips.hpp"

namespace facet::gpu {

std::size_t mip_chain_texels(int width, int height) {
  std::size_t texels = 0;
  for (const glm::uvec2 size : mip_chain_sizes(width, height)) texels += static_cast<std::size_t>(size.x) * size.y;
  return texels;
}

uint append_mip_chain(TextureData& data, int width, int height, MipLayout layout) {
  const uint first = static_cast<uint>(data.levels.size());
  const std::vector<glm::uvec2> sizes = mip_chain_sizes(width, height);
  for (uint l = 0; l < sizes.size(); ++l) {
    const glm::uvec2 size = sizes[l];
    data.levels.push_back({uvec4(data.texels.size(), size.x, size.y, l)});
    data.texels.grow(static_cast<std::size_t>(size.x) * size.y);  // level 0 for the caller, the rest for the GPU
  }
  data.gpu_chains.push_back({first, static_cast<uint>(sizes.size()), layout});
  return first;
}

std::span<vec4> level_texels(TextureData& data, uint level) {
  const uvec4 info = data.levels[level].info;
  return std::span<vec4>(data.texels.data() + info.x, static_cast<std::size_t>(info.y) * info.z);
}

double build_gpu_mips(vk::Context& context, const vk::Buffer& texels, const TextureData& data) {
  if (data.gpu_chains.empty()) return 0.0;
  MipBuilder builder(context);
  double gpu_ms = 0.0;
  for (const GpuMipChain& chain : data.gpu_chains)
    gpu_ms += builder.build(texels, std::span<const GpuTextureLevel>(data.levels).subspan(chain.first, chain.levels),
                            chain.layout);
  return gpu_ms;
}

double colormap_table_sigma_floor(const Colormap& map) {
  if (map.interpolation() != Colormap::Interpolation::Steps) return 0.0;
  return 0.01 * (map.domain().y - map.domain().x) * (map.positions().back() - map.positions().front());
}

precompute::PrefilteredColormap build_colormap_table(const ColormapTextureMaterial& material) {
  const Colormap& map = material.colormap;
  const auto [lo, hi] = std::minmax_element(material.texture->values.begin(), material.texture->values.end());
  precompute::PrefilteredColormapOptions options;
  options.tolerance = kColormapTableTolerance;
  options.sigma_max = 0.5 * (*hi - *lo);  // 0 (a constant texture): the builder's default
  options.sigma_floor = colormap_table_sigma_floor(map);
  return precompute::build_prefiltered_colormap(map, options);
}

bool colormap_searched_by_division(const Colormap& map) { return map.evenly_spaced() && map.positions().size() > 4; }

GpuColormap append_colormap_points(TextureData& data, const Colormap& map) {
  const GpuColormap record{
      uvec4(data.colormap_points.size(), map.positions().size(),
            map.interpolation() == Colormap::Interpolation::Steps ? 1 : 0, colormap_searched_by_division(map) ? 1 : 0),
      vec4(static_cast<float>(map.domain().x), static_cast<float>(map.domain().y), 0, 0), uvec4(0), vec4(0)};
  for (size_t i = 0; i < map.positions().size(); ++i)
    data.colormap_points.push_back(vec4(glm::vec3(map.colours()[i]), static_cast<float>(map.positions()[i])));
  return record;
}

uvec4 add_colormap_texture(TextureData& data, const ColormapTextureMaterial& material, bool with_table) {
  const assets::ScalarField& field = *material.texture;
  // Level 0 of each chain is written in place: the pairs (E[t], E[t^2] + within-texel variance) of a
  // texel and of its right neighbour, and the colour-mapped texel (rgb, 0), in float.
  const uint first_moment = append_mip_chain(data, field.width, field.height, MipLayout::Pairs);
  const uint moment_levels = static_cast<uint>(data.levels.size()) - first_moment;
  const uint first_colour = append_mip_chain(data, field.width, field.height);
  const std::span<vec4> moment_texels = level_texels(data, first_moment), colour_texels = level_texels(data, first_colour);
  static_assert(precompute::kScalarChannels == 3);
  // Rows in parallel: 16 bilinear samples per texel for the within-texel variance.
  tbb::parallel_for(0, field.height, [&](int y) {
    const std::size_t row = static_cast<std::size_t>(y) * field.width;
    glm::vec2 first{}, previous{};  // each texel is written once its right neighbour is known
    for (int x = 0; x < field.width; ++x) {
      const std::array<double, 3> m = precompute::scalar_moment_texel(field, x, y);
      const glm::vec2 pair(glm::dvec2(m[0], m[1] + m[2]));
      if (x == 0)
        first = pair;
      else
        moment_texels[row + x - 1] = vec4(previous, pair);
      previous = pair;
      colour_texels[row + x] = vec4(glm::vec3(material.colormap.at(field.values[row + x])), 0.0f);
    }
    moment_texels[row + field.width - 1] = vec4(previous, first);
  });

  const Colormap& map = material.colormap;
  GpuColormap gpu_map = append_colormap_points(data, map);
  if (with_table) {
    const precompute::PrefilteredColormap table = build_colormap_table(material);
    const kernels::f32::ColormapTableGrid grid = table.grid_f32();
    gpu_map.table = uvec4(data.texels.size(), grid.mu_count, grid.sigma_count, 0);
    gpu_map.table_range =
        vec4(grid.mu_min, grid.mu_max, grid.sigma_max, static_cast<float>(colormap_table_sigma_floor(map)));
    const std::vector<glm::vec4> rgba = table.rgba_f32();
    std::ranges::copy(rgba, data.texels.grow(rgba.size()).begin());
  }
  data.colormaps.push_back(gpu_map);
  return uvec4(first_moment, moment_levels, first_colour, data.colormaps.size() - 1);
}

std::size_t colormap_texture_texels(const ColormapTextureMaterial& material) {
  return 2 * mip_chain_texels(material.texture->width, material.texture->height);
}

}  // namespace facet::gpu
