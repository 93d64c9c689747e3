// Small Lambert scenes shared by the GPU pass tests: silhouettes, shadow edges and smooth shading in
// one small frame.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet::test {

// Two Lambert spheres on a ground plane under a directional light.
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

// A square pyramid (4 sides + base, 6 triangles) with flat shading, material 1.
inline Mesh pyramid(glm::dvec3 base_centre, double half_size, double height) {
  Mesh mesh;
  mesh.name = "pyramid";
  const glm::dvec3 c = base_centre;
  mesh.positions = {c + glm::dvec3(-half_size, 0, -half_size), c + glm::dvec3(half_size, 0, -half_size),
                    c + glm::dvec3(half_size, 0, half_size), c + glm::dvec3(-half_size, 0, half_size),
                    c + glm::dvec3(0, height, 0)};
  mesh.indices = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4, 0, 2, 1, 0, 3, 2};
  mesh.material = 1;
  return mesh;
}

// A coarse UV sphere (`rings` bands of latitude, `segments` of longitude) with radial vertex normals, material 1:
// near its silhouettes a face seen from the front has an interpolated normal leaning away from the viewer.
inline Mesh smooth_sphere(glm::dvec3 centre, double radius, int rings, int segments) {
  Mesh mesh;
  mesh.name = "smooth_sphere";
  const double pi = 3.14159265358979323846;
  for (int i = 0; i <= rings; ++i) {
    for (int j = 0; j <= segments; ++j) {
      const double polar = pi * i / rings, azimuth = 2.0 * pi * j / segments;
      const glm::dvec3 n(std::sin(polar) * std::cos(azimuth), std::cos(polar), std::sin(polar) * std::sin(azimuth));
      mesh.positions.push_back(centre + radius * n);
      mesh.normals.push_back(n);
    }
  }
  const auto vertex = [&](int i, int j) { return static_cast<uint32_t>(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      if (i > 0) mesh.indices.insert(mesh.indices.end(), {vertex(i, j), vertex(i, j + 1), vertex(i + 1, j)});
      if (i + 1 < rings)
        mesh.indices.insert(mesh.indices.end(), {vertex(i, j + 1), vertex(i + 1, j + 1), vertex(i + 1, j)});
    }
  }
  mesh.material = 1;
  return mesh;
}

}  // namespace facet::test
