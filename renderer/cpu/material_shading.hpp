// Shading of one surface sample on the CPU, in double: what the reference renderer computes per
// primary-ray hit (docs/reference.md). The Lambert and microflake lobes are the shared f64 kernels
// (shaders/lib/lambert.glsl, microflake_shading.glsl); the specular microfacet lobe uses the f64
// Beckmann D and Λ of shaders/lib/ndf_beckmann.glsl.
#pragma once

#include <glm/glm.hpp>

#include "assets/scalar_field.hpp"
#include "scene/scene.hpp"

namespace facet::cpu {

// The periodic texture at uv, bilinear between texel centres ((i + ½)/W, (j + ½)/H) (scene.hpp,
// ColormapTextureMaterial): the finest level, no filtering.
double sample_bilinear(const assets::ScalarField& texture, glm::dvec2 uv);

// height_colormap(z) · slope_colormap(|∇z|), each factor only when the material has it.
glm::dvec3 microsurface_albedo(const MicrosurfaceMaterial& material, double height, glm::dvec2 slope);

// Radiance of the Beckmann microfacet lobe lit by the directional light:
//   E · reflectance · D(h) G2(l, v) / (4 cos_v) · visibility,  G2 = 1 / (1 + Λ(l) + Λ(v)),
// in the frame (t, n × t, n) with t the plane tangent made perpendicular to the local normal n.
// Zero when l or v is below the local tangent plane.
glm::dvec3 beckmann_specular_radiance(const BeckmannSpecular& specular, glm::dvec3 n, glm::dvec3 tangent, glm::dvec3 v,
                                      glm::dvec3 l, glm::dvec3 light_irradiance, double visibility);

// A macro-surface sample (any material but microsurface): Lambert, microflake or colour-mapped texture,
// or the Lambertian base of a diffraction material (cpu/diffraction_shading.hpp adds its diffracted light).
// n: shading normal facing the viewer; v: unit direction toward the viewer; visibility of the light.
glm::dvec3 shade_macro_surface(const Scene& scene, const Material& material, glm::dvec3 n, glm::dvec3 v, glm::dvec2 uv,
                               double visibility);

}  // namespace facet::cpu
