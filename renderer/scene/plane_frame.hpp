// The tangent frame of a plane: the uv axes of its surface coordinates (scene.hpp, Plane).
#pragma once

#include <array>
#include <cmath>
#include <utility>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet {

// Orthonormal tangents of a unit normal (Duff et al. 2017, "Building an orthonormal basis, revisited"),
// with t1 × t2 = n.
inline std::pair<glm::dvec3, glm::dvec3> orthonormal_tangents(const glm::dvec3& n) {
  const double s = std::copysign(1.0, n.z);
  const double a = -1.0 / (s + n.z);
  const double b = n.x * n.y * a;
  return {{1.0 + s * n.x * n.x * a, s * b, -s * n.x}, {b, s + n.y * n.y * a, -n.y}};
}

struct PlaneFrame {
  glm::dvec3 tangent, bitangent, normal;  // right-handed: tangent × bitangent = normal
};

inline PlaneFrame plane_frame(const Plane& plane) {
  const glm::dvec3 n = glm::normalize(plane.normal);
  if (plane.tangent == glm::dvec3(0.0)) {
    const auto [t, b] = orthonormal_tangents(n);
    return {t, b, n};
  }
  const glm::dvec3 t = glm::normalize(plane.tangent - glm::dot(plane.tangent, n) * n);
  return {t, glm::cross(n, t), n};
}

// The four corners of a finite plane's rectangle (plane.size set).
inline std::array<glm::dvec3, 4> plane_rectangle_corners(const Plane& plane) {
  const PlaneFrame f = plane_frame(plane);
  const glm::dvec2 half = *plane.size * 0.5;
  return {
      plane.point - half.x * f.tangent - half.y * f.bitangent, plane.point + half.x * f.tangent - half.y * f.bitangent,
      plane.point - half.x * f.tangent + half.y * f.bitangent, plane.point + half.x * f.tangent + half.y * f.bitangent};
}

}  // namespace facet
