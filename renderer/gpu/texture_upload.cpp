#include "gpu/texture_upload.hpp"

#include "precompute/moment_mips.hpp"

namespace facet::gpu {

namespace {

// Appends a box-filtered MIP chain (precompute::build_moment_mips) of `channels` (<= 4) values per
// texel as vec4 texels; returns the index of its first level record.
uint append_mips(TextureData& data, int width, int height, int channels, std::vector<double> level0) {
  const precompute::MomentMips mips = precompute::build_moment_mips(width, height, channels, std::move(level0));
  const uint first = static_cast<uint>(data.levels.size());
  for (int l = 0; l < static_cast<int>(mips.levels.size()); ++l) {
    const precompute::MomentLevel& level = mips.levels[l];
    data.levels.push_back({uvec4(data.texels.size(), level.width, level.height, 0)});
    for (int y = 0; y < level.height; ++y)
      for (int x = 0; x < level.width; ++x) {
        const double* texel = mips.texel(l, x, y);
        vec4 v(0.0f);
        for (int c = 0; c < channels; ++c) v[c] = static_cast<float>(texel[c]);
        data.texels.push_back(v);
      }
  }
  return first;
}

}  // namespace

uvec4 add_colormap_texture(TextureData& data, const ColormapTextureMaterial& material) {
  const assets::ScalarField& field = *material.texture;
  std::vector<double> moments(2 * field.values.size()), colours(3 * field.values.size());
  for (size_t i = 0; i < field.values.size(); ++i) {
    const double t = field.values[i];
    moments[2 * i] = t;
    moments[2 * i + 1] = t * t;
    const glm::dvec3 c = material.colormap.at(t);
    for (int k = 0; k < 3; ++k) colours[3 * i + k] = c[k];
  }
  const uint first_moment = append_mips(data, field.width, field.height, 2, std::move(moments));
  const uint moment_levels = static_cast<uint>(data.levels.size()) - first_moment;
  const uint first_colour = append_mips(data, field.width, field.height, 3, std::move(colours));

  const Colormap& map = material.colormap;
  data.colormaps.push_back({uvec4(data.colormap_points.size(), map.positions().size(),
                                  map.interpolation() == Colormap::Interpolation::Steps ? 1 : 0, 0),
                            vec4(static_cast<float>(map.domain().x), static_cast<float>(map.domain().y), 0, 0)});
  for (size_t i = 0; i < map.positions().size(); ++i)
    data.colormap_points.push_back(vec4(glm::vec3(map.colours()[i]), static_cast<float>(map.positions()[i])));
  return uvec4(first_moment, moment_levels, first_colour, data.colormaps.size() - 1);
}

}  // namespace facet::gpu
