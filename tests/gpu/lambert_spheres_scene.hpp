// Two Lambert spheres on a ground plane under a directional light: silhouettes, shadow edges and
// smooth shading in one small frame (the GPU pass tests' common scene).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet::test {

inline Scene lambert_spheres_scene() {
  Scene scene;
  scene.camera.position = {0.0, 1.5, 6.0};
  scene.camera.target = {0.0, 0.7, 0.0};
  scene.camera.fov_y_deg = 40.0;
  scene.light.direction = glm::normalize(glm::dvec3(0.4, 1.0, 0.3));
  scene.light.irradiance = {3.0, 2.8, 2.6};
  scene.ambient = {0.1, 0.12, 0.15};
  scene.background = {0.2, 0.3, 0.4};
  scene.materials = {LambertMaterial{{0.8, 0.8, 0.8}}, LambertMaterial{{0.9, 0.2, 0.1}}};
  scene.planes.push_back({{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0});
  scene.spheres.push_back({{-0.8, 0.7, 0.0}, 0.7, 1});
  scene.spheres.push_back({{1.0, 0.5, 0.8}, 0.5, 0});
  return scene;
}

}  // namespace facet::test
