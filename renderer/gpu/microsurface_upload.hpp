// A microsurface material as GPU data (docs/microsurface_filtering.md). In the shared texel buffer:
//   level `first`: the vertex heights z(i, j) - z_offset of the field (world units), from which the
//     rest is built;
//   then three MIP chains of `count` levels over the field's cells (texel (i, j) = the bilinear patch
//   between vertices i..i+1, j..j+1, so texel centres sit where sample_level expects them):
//     moments  (E[z], E[z^2], E[s_x], E[s_y])        exact over each patch, heights minus z_offset,
//     slopes   (E[s_x^2], E[s_y^2], E[s_x s_y], 0)    slopes s = grad z in world units,
//     albedo   (mean height_colormap(z) slope_colormap(|s|) over the patch, 0), for colormip.
// Coarser levels are box means (append_mip_chain), i.e. the moments over the covered patches.
// Then, for the tracer (render/heightfield_trace.glsl), built on the CPU: the min-max MIP of the cells
// (min, max, -, -), `count` levels of the same sizes, in heightfield_bound_span texels, level l at
// FACET_HEIGHTFIELD_BOUND_LEVEL(span, l) after level 0 (unused texels between); then each cell's four
// vertex heights in one texel (z00, z10, z01, z11): the tracer's cells, and the point lookups of
// (H1)-(H2) (naive, filtered under magnification); then the visible-height nodes of filtered's statistics
// (precompute/visible_height_nodes.hpp), texel i MS_HEIGHT_NODES + k holding node k at grid points i and i + 1.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gpu/scene_layout.hpp"
#include "gpu/texture_upload.hpp"
#include "scene/scene.hpp"

namespace facet::gpu {

// Appends the vertex level, the three chains and the colour maps; returns the material record:
//   albedo  (specular reflectance rgb, texel size)
//   kind    (FACET_MATERIAL_MICROSURFACE, 1 if it has a specular lobe, first min-max level, its level count)
//   params  (alpha_x, alpha_y, z_offset, -)
//   texture (first level = vertex level, chain level count, height map, slope map (or FACET_NO_COLORMAP))
GpuMaterial add_microsurface(TextureData& data, const MicrosurfaceMaterial& material);

// The texels add_microsurface appends, so that the upload can reserve them before it builds them.
std::size_t microsurface_texels(const MicrosurfaceMaterial& material);

// The texels of one min-max chain over a width x height field: 2A, A = the largest over levels l of
// the level's texels times 2^l, so that FACET_HEIGHTFIELD_BOUND_LEVEL(2A, l) leaves each level room
// before the next (docs/render_speed.md, "A step of the height-field tracer").
uint heightfield_bound_span(int width, int height);

}  // namespace facet::gpu
