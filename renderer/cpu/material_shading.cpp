#include "cpu/material_shading.hpp"

#include <cmath>
#include <type_traits>
#include <variant>

#include "kernels/shared.hpp"

namespace facet::cpu {

namespace k = kernels::f64;

double sample_bilinear(const assets::ScalarField& texture, glm::dvec2 uv) {
  // Texel centres sit at integer + ½ in texel units; floor() keeps negative uv on the right cell.
  const double x = uv.x * texture.width - 0.5, y = uv.y * texture.height - 0.5;
  const double fx = std::floor(x), fy = std::floor(y);
  const double u = x - fx, v = y - fy;
  // One wrap per axis (the neighbour wraps by comparison): integer division is the costly part.
  const auto wrap = [](double f, int n) {
    const long long i = static_cast<long long>(f) % n;
    return static_cast<int>(i < 0 ? i + n : i);
  };
  const int i0 = wrap(fx, texture.width), j0 = wrap(fy, texture.height);
  const int i1 = i0 + 1 == texture.width ? 0 : i0 + 1, j1 = j0 + 1 == texture.height ? 0 : j0 + 1;
  const double z00 = texture.at(i0, j0), z10 = texture.at(i1, j0), z01 = texture.at(i0, j1), z11 = texture.at(i1, j1);
  return (1.0 - v) * ((1.0 - u) * z00 + u * z10) + v * ((1.0 - u) * z01 + u * z11);
}

glm::dvec3 microsurface_albedo(const MicrosurfaceMaterial& material, double height, glm::dvec2 slope) {
  glm::dvec3 albedo(1.0);
  if (material.height_colormap) albedo *= material.height_colormap->at(height);
  if (material.slope_colormap) albedo *= material.slope_colormap->at(glm::length(slope));
  return albedo;
}

glm::dvec3 beckmann_specular_radiance(const BeckmannSpecular& specular, glm::dvec3 n, glm::dvec3 tangent, glm::dvec3 v,
                                      glm::dvec3 l, glm::dvec3 light_irradiance, double visibility) {
  if (visibility == 0.0) return glm::dvec3(0.0);
  const double f_cos = k::beckmann_facet_specular(n, tangent, v, l, specular.alpha);
  return light_irradiance * specular.reflectance * (f_cos * visibility);
}

glm::dvec3 shade_macro_surface(const Scene& scene, const Material& material, glm::dvec3 n, glm::dvec3 v, glm::dvec2 uv,
                               double visibility) {
  const glm::dvec3 l = scene.light.direction;
  return std::visit(
      [&](const auto& m) -> glm::dvec3 {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, LambertMaterial>) {
          return k::lambert_radiance(m.albedo, n, l, scene.light.irradiance, visibility, scene.ambient);
        } else if constexpr (std::is_same_v<M, MicroflakeMaterial>) {
          return k::microflake_radiance(static_cast<int>(m.ndf), m.param, m.albedo, n, v, l, scene.light.irradiance,
                                        visibility, scene.ambient);
        } else if constexpr (std::is_same_v<M, ColormapTextureMaterial>) {
          const glm::dvec3 albedo = m.colormap.at(sample_bilinear(*m.texture, uv));
          return k::lambert_radiance(albedo, n, l, scene.light.irradiance, visibility, scene.ambient);
        } else if constexpr (std::is_same_v<M, DiffractionMaterial>) {
          // The diffuse base only; DiffractionShading adds the diffracted light (it needs the tables).
          return k::lambert_radiance(m.base_albedo, n, l, scene.light.irradiance, visibility, scene.ambient);
        } else {
          static_assert(std::is_same_v<M, MicrosurfaceMaterial>);
          return glm::dvec3(0.0);  // never reached: microsurfaces are traced as height fields
        }
      },
      material);
}

}  // namespace facet::cpu
