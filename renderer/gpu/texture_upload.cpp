#include "gpu/texture_upload.hpp"

#include <algorithm>

namespace facet::gpu {

namespace {

// Appends a MIP chain built by 2x2 box filtering with wrap-around (the textures are periodic);
// level l + 1 has ceil(size / 2) texels per side, so an odd side's last texel is averaged with the
// first one of its row or column. Returns the index of the first level record.
uint append_box_mips(TextureData& data, std::vector<vec4> level, int width, int height, uint& level_count) {
  const uint first = static_cast<uint>(data.levels.size());
  level_count = 0;
  while (true) {
    data.levels.push_back({uvec4(data.texels.size(), width, height, 0)});
    data.texels.insert(data.texels.end(), level.begin(), level.end());
    ++level_count;
    if (width == 1 && height == 1) break;
    const int w2 = (width + 1) / 2, h2 = (height + 1) / 2;
    std::vector<vec4> next(static_cast<size_t>(w2) * h2);
    for (int j = 0; j < h2; ++j)
      for (int i = 0; i < w2; ++i) {
        auto at = [&](int x, int y) { return level[static_cast<size_t>(y % height) * width + x % width]; };
        next[static_cast<size_t>(j) * w2 + i] =
            0.25f * (at(2 * i, 2 * j) + at(2 * i + 1, 2 * j) + at(2 * i, 2 * j + 1) + at(2 * i + 1, 2 * j + 1));
      }
    level = std::move(next);
    width = w2;
    height = h2;
  }
  return first;
}

}  // namespace

uvec4 add_colormap_texture(TextureData& data, const ColormapTextureMaterial& material) {
  const assets::ScalarField& field = *material.texture;
  std::vector<vec4> moments(field.values.size()), colours(field.values.size());
  for (size_t i = 0; i < field.values.size(); ++i) {
    const double t = field.values[i];
    moments[i] = vec4(static_cast<float>(t), static_cast<float>(t * t), 0.0f, 0.0f);
    colours[i] = vec4(glm::vec3(material.colormap.at(t)), 0.0f);
  }
  uint moment_levels = 0, colour_levels = 0;
  const uint first_moment = append_box_mips(data, std::move(moments), field.width, field.height, moment_levels);
  const uint first_colour = append_box_mips(data, std::move(colours), field.width, field.height, colour_levels);

  const Colormap& map = material.colormap;
  data.colormaps.push_back({uvec4(data.colormap_points.size(), map.positions().size(),
                                  map.interpolation() == Colormap::Interpolation::Steps ? 1 : 0, 0),
                            vec4(static_cast<float>(map.domain().x), static_cast<float>(map.domain().y), 0, 0)});
  for (size_t i = 0; i < map.positions().size(); ++i)
    data.colormap_points.push_back(vec4(glm::vec3(map.colours()[i]), static_cast<float>(map.positions()[i])));
  return uvec4(first_moment, moment_levels, first_colour, data.colormaps.size() - 1);
}

}  // namespace facet::gpu
