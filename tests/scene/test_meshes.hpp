// Test-only triangle soups for the BVH and ray caster tests.
#pragma once

#include <random>
#include <vector>

#include "scene/scene.hpp"

namespace facet::test {

// `count` random triangles with vertices in [center - extent, center + extent]^3, each with
// edges up to `size` long; flat (no normals) unless `with_normals`.
inline Mesh random_triangles(std::mt19937& rng, size_t count, glm::dvec3 center, double extent, double size,
                             bool with_normals = false) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Mesh m;
  for (size_t t = 0; t < count; ++t) {
    const glm::dvec3 a = center + extent * glm::dvec3(u(rng), u(rng), u(rng));
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 p = k == 0 ? a : a + size * glm::dvec3(u(rng), u(rng), u(rng));
      m.indices.push_back(static_cast<uint32_t>(m.positions.size()));
      m.positions.push_back(p);
      if (with_normals) m.normals.push_back(glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(0, 0, 2)));
    }
  }
  return m;
}

}  // namespace facet::test
