// Small scenes built in code for the reference renderer tests.
#pragma once

#include <cmath>
#include <numbers>

#include "scene/scene.hpp"

namespace facet::test {

// A camera at height `h` looking straight down at the origin (up = −z) with a square film.
inline Camera overhead_camera(double h, double fov_y_deg, int side) {
  return {{0.0, h, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, fov_y_deg, side, side};
}

// A light straight down with irradiance π and no ambient: a Lambertian sample facing up then has
// radiance equal to its albedo. With `ambient_only`, irradiance 0 and ambient π: radiance = albedo
// whatever the normal and shadowing.
inline void unit_lighting(Scene& scene, bool ambient_only) {
  scene.light.direction = {0.0, 1.0, 0.0};
  scene.light.irradiance = glm::dvec3(ambient_only ? 0.0 : std::numbers::pi);
  scene.ambient = glm::dvec3(ambient_only ? std::numbers::pi : 0.0);
  scene.background = glm::dvec3(0.0);
}

// Black below `threshold`, white from it on.
inline Colormap step_map(double threshold, glm::dvec2 domain = {0.0, 1.0}) {
  return Colormap({0.0, threshold}, {glm::dvec3(0.0), glm::dvec3(1.0)}, Colormap::Interpolation::Steps, domain);
}

}  // namespace facet::test
