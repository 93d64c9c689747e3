// The camera's orthonormal frame, scaled for camera_ray_direction() (shaders/lib/camera.glsl).
#pragma once

#include <cmath>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet {

struct CameraFrame {
  glm::dvec3 origin;
  glm::dvec3 forward;  // unit
  glm::dvec3 right;    // unit right * tan(fov_y / 2) * aspect
  glm::dvec3 up;       // unit up * tan(fov_y / 2)
};

inline CameraFrame camera_frame(const Camera& camera, int width, int height) {
  glm::dvec3 forward = glm::normalize(camera.target - camera.position);
  glm::dvec3 right = glm::normalize(glm::cross(forward, camera.up));
  glm::dvec3 up = glm::cross(right, forward);
  double tan_half = std::tan(glm::radians(camera.fov_y_deg) / 2.0);
  return {camera.position, forward, right * (tan_half * width / height), up * tan_half};
}

}  // namespace facet
