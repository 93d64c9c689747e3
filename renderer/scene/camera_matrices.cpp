#include "scene/camera_matrices.hpp"

#include <algorithm>
#include <cmath>

#include "scene/camera_frame.hpp"

namespace facet {

namespace {

// pbrt-v4's near and far planes of a perspective camera.
constexpr double kNear = 1e-2;
constexpr double kFar = 1000.0;

}  // namespace

glm::dmat4 world_to_camera(const Camera& camera) {
  // The frame's axes at unit length (its aspect and field of view do not matter here).
  const CameraFrame frame = camera_frame(camera, 1, 1);
  const glm::dvec3 x = glm::normalize(frame.right), y = glm::normalize(frame.up), z = frame.forward;
  // glm is column-major: m[column][row]. Rows are the axes; column 3 moves the eye to the origin.
  glm::dmat4 m(1.0);
  for (int i = 0; i < 3; ++i) {
    m[i][0] = x[i];
    m[i][1] = y[i];
    m[i][2] = z[i];
  }
  m[3] = glm::dvec4(-glm::dot(x, camera.position), -glm::dot(y, camera.position), -glm::dot(z, camera.position), 1.0);
  return m;
}

glm::dmat4 world_to_ndc(const Camera& camera, int width, int height) {
  // tan of half the shorter side's field of view: the vertical one, widened for a portrait image.
  const double tan_half_y = std::tan(glm::radians(camera.fov_y_deg) / 2.0);
  const double tan_half_short = tan_half_y * std::min(1.0, double(width) / height);
  const double s = 1.0 / tan_half_short;
  // Perspective(fov, n, f): x' = s x, y' = s y, z' = f (z - n) / (f - n), w' = z (column-major below).
  glm::dmat4 screen_from_camera(0.0);
  screen_from_camera[0][0] = s;
  screen_from_camera[1][1] = s;
  screen_from_camera[2][2] = kFar / (kFar - kNear);
  screen_from_camera[3][2] = -kFar * kNear / (kFar - kNear);
  screen_from_camera[2][3] = 1.0;
  // [-1, 1] -> [0, 1] on every axis.
  glm::dmat4 ndc_from_screen(0.5);
  ndc_from_screen[3] = glm::dvec4(0.5, 0.5, 0.5, 1.0);
  return ndc_from_screen * screen_from_camera * world_to_camera(camera);
}

}  // namespace facet
