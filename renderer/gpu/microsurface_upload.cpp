#include "gpu/microsurface_upload.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include <tbb/parallel_for.h>

#include "common/error.hpp"
#include "gpu/mip_builder.hpp"
#include "kernels/shared.hpp"
#include "layout/heightfield_layout.glsl"
#include "precompute/visible_height_nodes.hpp"

namespace facet::gpu {

namespace {

// Points per axis of the midpoint rule for a patch's mean albedo (colormip only).
constexpr int kAlbedoPoints = 4;

// The bilinear patch z = z00 + b u + c v + e u v, (u, v) in [0, 1]^2 (docs/assets.md (H1)).
struct Patch {
  double z00, b, c, e;
};

// The min-max MIP of the field's cells for the GPU tracer (render/heightfield_trace.glsl): level 0
// holds (min, max) of each cell's four vertex heights as stored (float, so the bounds hold exactly
// what the tracer reads), each coarser level the extremes of its 2 x 2 children, down to 1 x 1.
// Returns the first level record; the chain has mip_chain_sizes(width, height).size() levels, laid
// out as heightfield_bound_span says.
uint append_height_bounds(TextureData& data, uint vertex_level) {
  const uvec4 info = data.levels[vertex_level].info;
  const int w = static_cast<int>(info.y), h = static_cast<int>(info.z);
  const auto z = [&](int i, int j) { return data.texels[info.x + static_cast<size_t>(j % h) * w + (i % w)].x; };
  const uint first = static_cast<uint>(data.levels.size());
  const std::vector<glm::uvec2> sizes = mip_chain_sizes(w, h);
  const uint span = heightfield_bound_span(w, h);
  const size_t base = data.texels.size();
  data.texels.grow(span);  // the texels between the levels are never read
  for (size_t l = 0; l < sizes.size(); ++l) {
    const uint offset = static_cast<uint>(base + FACET_HEIGHTFIELD_BOUND_LEVEL(span, l));
    data.levels.push_back({uvec4(offset, sizes[l].x, sizes[l].y, l)});
    for (uint j = 0; j < sizes[l].y; ++j)
      for (uint i = 0; i < sizes[l].x; ++i) {
        float lo = std::numeric_limits<float>::infinity(), hi = -lo;
        if (l == 0) {
          for (int c = 0; c < 4; ++c) {
            const float v = z(static_cast<int>(i) + (c & 1), static_cast<int>(j) + (c >> 1));
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
        } else {  // children outside the finer level (odd sizes) are skipped
          const uvec4 fine = data.levels[first + l - 1].info;
          for (uint c = 0; c < 4; ++c) {
            const uint fi = 2 * i + (c & 1), fj = 2 * j + (c >> 1);
            if (fi >= fine.y || fj >= fine.z) continue;
            const vec4 b = data.texels[fine.x + static_cast<size_t>(fj) * fine.y + fi];
            lo = std::min(lo, b.x);
            hi = std::max(hi, b.y);
          }
        }
        data.texels[offset + static_cast<size_t>(j) * sizes[l].x + i] = vec4(lo, hi, 0.0f, 0.0f);
      }
  }
  return first;
}

// The visible-height node table (precompute/visible_height_nodes.hpp) as one level: texel i MS_HEIGHT_NODES + k
// holds node k at grid points i and i + 1 (the last point twice), so the shader's interpolation reads one texel.
void append_visible_height_nodes(TextureData& data) {
  static const std::vector<double> table = precompute::visible_height_node_table();
  data.levels.push_back({uvec4(data.texels.size(), MS_NODE_TABLE_POINTS, MS_HEIGHT_NODES, 0)});
  const auto z = [](int i, int k) {
    return static_cast<float>(table[static_cast<std::size_t>(i) * MS_HEIGHT_NODES + k]);
  };
  for (int i = 0; i < MS_NODE_TABLE_POINTS; ++i)
    for (int k = 0; k < MS_HEIGHT_NODES; ++k)
      data.texels.push_back(vec4(z(i, k), z(std::min(i + 1, MS_NODE_TABLE_POINTS - 1), k), 0.0f, 0.0f));
}

// Each cell's four vertex heights (z00, z10, z01, z11) in one texel, the last vertex wrapping to the
// first (the field repeats): the tracer loads a cell's corners in one fetch instead of four, and the
// point lookups of (H1)-(H2) read them too.
void append_corner_quads(TextureData& data, uint vertex_level) {
  const uvec4 grid = data.levels[vertex_level].info;
  const uint w = grid.y, h = grid.z;
  data.levels.push_back({uvec4(data.texels.size(), w, h, 0)});
  for (uint j = 0; j < h; ++j)
    for (uint i = 0; i < w; ++i) {
      const auto z = [&](uint a, uint b) { return data.texels[grid.x + static_cast<size_t>(b % h) * w + a % w].x; };
      data.texels.push_back(vec4(z(i, j), z(i + 1, j), z(i, j + 1), z(i + 1, j + 1)));
    }
}

// The level-0 texels of the three chains, written in place (width * height each).
void fill_microsurface_level0(const MicrosurfaceMaterial& material, double z_offset, std::span<vec4> moments,
                              std::span<vec4> slopes, std::span<vec4> albedos) {
  const assets::ScalarField& field = *material.heights;
  const double scale = material.height_scale, inv_delta = 1.0 / material.texel_size;
  // 2-point Gauss-Legendre on [0, 1] per axis: exact for z^2, which is biquadratic in (u, v).
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  // Rows in parallel: 4 + kAlbedoPoints² evaluations and colour-map look-ups per texel.
  tbb::parallel_for(0, field.height, [&](int j) {
    for (int i = 0; i < field.width; ++i) {
      const size_t texel = static_cast<size_t>(j) * field.width + i;
      const double z00 = scale * field.at(i, j) - z_offset, z10 = scale * field.wrapped(i + 1, j) - z_offset;
      const double z01 = scale * field.wrapped(i, j + 1) - z_offset,
                   z11 = scale * field.wrapped(i + 1, j + 1) - z_offset;
      const Patch p{z00, z10 - z00, z01 - z00, z00 - z10 - z01 + z11};
      double z2 = 0.0;
      for (double u : g)
        for (double v : g) z2 += 0.25 * std::pow(p.z00 + p.b * u + p.c * v + p.e * u * v, 2);
      // (H2): s_x = (b + e v)/delta depends on v only, s_y = (c + e u)/delta on u only, so over the
      // patch E[s_x^2] = (b^2 + b e + e^2/3)/delta^2 and E[s_x s_y] = E[s_x] E[s_y].
      const double sx = (p.b + 0.5 * p.e) * inv_delta, sy = (p.c + 0.5 * p.e) * inv_delta;
      const double sx2 = (p.b * p.b + p.b * p.e + p.e * p.e / 3.0) * inv_delta * inv_delta;
      const double sy2 = (p.c * p.c + p.c * p.e + p.e * p.e / 3.0) * inv_delta * inv_delta;
      moments[texel] = vec4(0.25 * (z00 + z10 + z01 + z11), z2, sx, sy);
      slopes[texel] = vec4(sx2, sy2, sx * sy, 0.0);
      glm::dvec3 albedo(0.0);
      for (int a = 0; a < kAlbedoPoints; ++a)
        for (int b = 0; b < kAlbedoPoints; ++b) {
          const double u = (a + 0.5) / kAlbedoPoints, v = (b + 0.5) / kAlbedoPoints;
          const double z = p.z00 + p.b * u + p.c * v + p.e * u * v + z_offset;
          const glm::dvec2 s((p.b + p.e * v) * inv_delta, (p.c + p.e * u) * inv_delta);
          glm::dvec3 c(1.0);
          if (material.height_colormap) c *= material.height_colormap->at(z);
          if (material.slope_colormap) c *= material.slope_colormap->at(glm::length(s));
          albedo += c;
        }
      albedos[texel] = vec4(glm::vec3(albedo / double(kAlbedoPoints * kAlbedoPoints)), 0.0f);
    }
  });
}

}  // namespace

std::size_t microsurface_texels(const MicrosurfaceMaterial& material) {
  const int w = material.heights->width, h = material.heights->height;
  const std::size_t chain = mip_chain_texels(w, h), vertices = static_cast<std::size_t>(w) * h;
  // The vertex level, three box-filtered chains, the min-max chain, the corner quads and the visible-height
  // nodes (add_microsurface).
  return vertices + 3 * chain + std::size_t{heightfield_bound_span(w, h)} + vertices +
         std::size_t{MS_NODE_TABLE_POINTS} * MS_HEIGHT_NODES;
}

uint heightfield_bound_span(int width, int height) {
  // Level l then starts at 2A - (2A >> l) and the next at 2A - (2A >> (l + 1)), ceil((2A >> l) / 2)
  // texels later, which is at least A / 2^l - 1/2 and so, being whole, at least the level's texels.
  std::uint64_t a = 0;
  const std::vector<glm::uvec2> sizes = mip_chain_sizes(width, height);
  for (size_t l = 0; l < sizes.size(); ++l) a = std::max(a, (std::uint64_t{sizes[l].x} * sizes[l].y) << l);
  if (2 * a > std::numeric_limits<uint>::max())
    throw Error("microsurface: a " + std::to_string(width) + "x" + std::to_string(height) +
                " height field is too large for the tracer's bounds");
  return static_cast<uint>(2 * a);
}

GpuMaterial add_microsurface(TextureData& data, const MicrosurfaceMaterial& material) {
  const assets::ScalarField& field = *material.heights;
  // Heights are stored about their mean, so E[z^2] - E[z]^2 does not cancel in float.
  double mean = 0.0;
  for (double h : field.values) mean += h;
  const double z_offset = material.height_scale * mean / static_cast<double>(field.values.size());

  const uint first = static_cast<uint>(data.levels.size());
  data.levels.push_back({uvec4(data.texels.size(), field.width, field.height, 0)});
  for (double h : field.values)
    data.texels.push_back(vec4(static_cast<float>(material.height_scale * h - z_offset), 0, 0, 0));
  const uint moments = append_mip_chain(data, field.width, field.height);
  const uint slopes = append_mip_chain(data, field.width, field.height);
  const uint albedos = append_mip_chain(data, field.width, field.height);
  fill_microsurface_level0(material, z_offset, level_texels(data, moments), level_texels(data, slopes),
                           level_texels(data, albedos));
  const uint count = static_cast<uint>(mip_chain_sizes(field.width, field.height).size());
  const uint bounds = append_height_bounds(data, first);
  append_corner_quads(data, first);
  append_visible_height_nodes(data);

  const auto add_map = [&](const std::optional<Colormap>& map) {
    if (!map) return FACET_NO_COLORMAP;
    data.colormaps.push_back(append_colormap_points(data, *map));
    return static_cast<uint>(data.colormaps.size() - 1);
  };
  const uint height_map = add_map(material.height_colormap);
  const uint slope_map = add_map(material.slope_colormap);
  const glm::dvec2 alpha = material.specular ? material.specular->alpha : glm::dvec2(1.0);
  const glm::dvec3 reflectance = material.specular ? material.specular->reflectance : glm::dvec3(0.0);
  return {vec4(glm::vec3(reflectance), static_cast<float>(material.texel_size)),
          uvec4(FACET_MATERIAL_MICROSURFACE, material.specular ? 1u : 0u, bounds, count),
          vec4(static_cast<float>(alpha.x), static_cast<float>(alpha.y), static_cast<float>(z_offset), 0.0f),
          uvec4(first, count, height_map, slope_map)};
}

}  // namespace facet::gpu
