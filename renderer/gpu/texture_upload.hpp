// The colour-mapped textures of a scene as GPU data: per texture a MIP chain of moments
// (E[t], E[t^2]) and a MIP chain of the colour-mapped texture (for the `colormip` baseline), both
// box-filtered by precompute::build_moment_mips, and
// the colour maps as control points (layouts in shaders/layout/scene_layout.glsl).
#pragma once

#include <vector>

#include "gpu/scene_layout.hpp"
#include "scene/scene.hpp"

namespace facet::gpu {

struct TextureData {
  std::vector<GpuTextureLevel> levels;
  std::vector<vec4> texels;
  std::vector<GpuColormap> colormaps;
  std::vector<vec4> colormap_points;  // linear rgb, position
};

// Appends the MIP chains of `material` and its colour map; returns the GpuMaterial::texture field
// (first moment level, level count, first colour-MIP level, colour map index).
uvec4 add_colormap_texture(TextureData& data, const ColormapTextureMaterial& material);

}  // namespace facet::gpu
