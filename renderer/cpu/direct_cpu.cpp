#include "cpu/direct_cpu.hpp"

#include <cmath>
#include <variant>

#include <tbb/parallel_for.h>

#include "common/error.hpp"
#include "cpu/material_shading.hpp"
#include "cpu/ray_caster.hpp"
#include "kernels/shared.hpp"
#include "scene/camera_frame.hpp"

namespace facet::cpu {

namespace k = kernels::f64;

Image render_direct_cpu(const Scene& scene, int width, int height, const diffraction::DiffractionSettings& diffraction,
                        DiffractionShading::Transform transform) {
  // The twin of the GPU pass renders what it renders; sub-pixel materials are the reference's.
  for (size_t i = 0; i < scene.materials.size(); ++i) {
    if (std::holds_alternative<ColormapTextureMaterial>(scene.materials[i]) ||
        std::holds_alternative<MicrosurfaceMaterial>(scene.materials[i]))
      throw Error("material '" + scene.material_names[i] + "' (" + material_type_name(scene.materials[i]) +
                  ") is not supported by the direct pass; use facet reference");
  }
  const CameraFrame camera = camera_frame(scene.camera, width, height);
  const glm::dvec2 resolution(width, height);
  const glm::dvec3 l = scene.light.direction;

  RayCaster caster(scene);
  const DiffractionShading diffracted(scene, transform, diffraction);
  Image image(width, height);
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      glm::dvec3 d =
          k::camera_ray_direction(camera.forward, camera.right, camera.up, glm::dvec2(x + 0.5, y + 0.5), resolution);
      glm::dvec3 color = scene.background;
      if (auto hit = caster.intersect(camera.origin, d)) {
        glm::dvec3 n = hit->shading_normal;
        // Same scale-relative offset as the GPU pass (shaders/render/direct_pass.glsl).
        glm::dvec3 origin = hit->position + n * (1e-4 * std::max(1.0, glm::length(hit->position)));
        double visibility = glm::dot(n, l) > 0.0 && caster.occluded(origin, l, INFINITY) ? 0.0 : 1.0;
        color = shade_macro_surface(scene, scene.materials[hit->material], n, -d, hit->uv, visibility);
        if (diffracted.handles(hit->material))
          color += diffracted.radiance(hit->material, n, hit->back_face, hit->dpdu, -d, visibility);
      }
      image.set(x, y, glm::vec3(color));
    }
  });
  return image;
}

}  // namespace facet::cpu
