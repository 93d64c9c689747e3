#include "gpu/microsurface_upload.hpp"

#include <cmath>

#include "gpu/mip_builder.hpp"

namespace facet::gpu {

namespace {

// Points per axis of the midpoint rule for a patch's mean albedo (colormip only).
constexpr int kAlbedoPoints = 4;

// The bilinear patch z = z00 + b u + c v + e u v, (u, v) in [0, 1]^2 (docs/assets.md (H1)).
struct Patch {
  double z00, b, c, e;
};

}  // namespace

MicrosurfaceLevel0 microsurface_level0(const MicrosurfaceMaterial& material, double z_offset) {
  const assets::ScalarField& field = *material.heights;
  const double scale = material.height_scale, inv_delta = 1.0 / material.texel_size;
  // 2-point Gauss-Legendre on [0, 1] per axis: exact for z^2, which is biquadratic in (u, v).
  const double g[2] = {0.5 - 0.5 / std::sqrt(3.0), 0.5 + 0.5 / std::sqrt(3.0)};
  MicrosurfaceLevel0 out;
  const size_t n = field.values.size();
  out.moments.reserve(n);
  out.slopes.reserve(n);
  out.albedo.reserve(n);
  for (int j = 0; j < field.height; ++j)
    for (int i = 0; i < field.width; ++i) {
      const double z00 = scale * field.at(i, j) - z_offset, z10 = scale * field.wrapped(i + 1, j) - z_offset;
      const double z01 = scale * field.wrapped(i, j + 1) - z_offset, z11 = scale * field.wrapped(i + 1, j + 1) - z_offset;
      const Patch p{z00, z10 - z00, z01 - z00, z00 - z10 - z01 + z11};
      double z2 = 0.0;
      for (double u : g)
        for (double v : g) z2 += 0.25 * std::pow(p.z00 + p.b * u + p.c * v + p.e * u * v, 2);
      // (H2): s_x = (b + e v)/delta depends on v only, s_y = (c + e u)/delta on u only, so over the
      // patch E[s_x^2] = (b^2 + b e + e^2/3)/delta^2 and E[s_x s_y] = E[s_x] E[s_y].
      const double sx = (p.b + 0.5 * p.e) * inv_delta, sy = (p.c + 0.5 * p.e) * inv_delta;
      const double sx2 = (p.b * p.b + p.b * p.e + p.e * p.e / 3.0) * inv_delta * inv_delta;
      const double sy2 = (p.c * p.c + p.c * p.e + p.e * p.e / 3.0) * inv_delta * inv_delta;
      out.moments.push_back(vec4(0.25 * (z00 + z10 + z01 + z11), z2, sx, sy));
      out.slopes.push_back(vec4(sx2, sy2, sx * sy, 0.0));
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
      out.albedo.push_back(vec4(glm::vec3(albedo / double(kAlbedoPoints * kAlbedoPoints)), 0.0f));
    }
  return out;
}

GpuMaterial add_microsurface(TextureData& data, const MicrosurfaceMaterial& material) {
  const assets::ScalarField& field = *material.heights;
  // Heights are stored about their mean, so E[z^2] - E[z]^2 does not cancel in float.
  double mean = 0.0;
  for (double h : field.values) mean += h;
  const double z_offset = material.height_scale * mean / static_cast<double>(field.values.size());

  const uint first = static_cast<uint>(data.levels.size());
  data.levels.push_back({uvec4(data.texels.size(), field.width, field.height, 0)});
  for (double h : field.values) data.texels.push_back(vec4(static_cast<float>(material.height_scale * h - z_offset), 0, 0, 0));
  const MicrosurfaceLevel0 level0 = microsurface_level0(material, z_offset);
  append_mip_chain(data, field.width, field.height, level0.moments);
  append_mip_chain(data, field.width, field.height, level0.slopes);
  append_mip_chain(data, field.width, field.height, level0.albedo);
  const uint count = static_cast<uint>(mip_chain_sizes(field.width, field.height).size());

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
          uvec4(FACET_MATERIAL_MICROSURFACE, material.specular ? 1u : 0u, 0, 0),
          vec4(static_cast<float>(alpha.x), static_cast<float>(alpha.y), static_cast<float>(z_offset), 0.0f),
          uvec4(first, count, height_map, slope_map)};
}

}  // namespace facet::gpu
