#include "scene/camera_path.hpp"

#include <algorithm>
#include <string>

#include "common/error.hpp"

namespace facet {

namespace {

struct Pose {
  glm::dvec3 position;
  glm::dvec3 target;
  double fov_y_deg;
};

Pose pose(const CameraKey& key) { return {key.position, key.target, key.fov_y_deg}; }

Pose operator+(const Pose& a, const Pose& b) {
  return {a.position + b.position, a.target + b.target, a.fov_y_deg + b.fov_y_deg};
}
Pose operator-(const Pose& a, const Pose& b) {
  return {a.position - b.position, a.target - b.target, a.fov_y_deg - b.fov_y_deg};
}
Pose operator*(double s, const Pose& a) { return {s * a.position, s * a.target, s * a.fov_y_deg}; }

// The smooth path's velocity (pose units per frame) at key i: Catmull-Rom's central difference over
// the neighbouring keys in time, zero at the first and last key (the camera starts and stops at rest).
Pose key_velocity(const std::vector<CameraKey>& keys, size_t i) {
  if (i == 0 || i + 1 == keys.size()) return Pose{glm::dvec3(0.0), glm::dvec3(0.0), 0.0};
  return (1.0 / (keys[i + 1].frame - keys[i - 1].frame)) * (pose(keys[i + 1]) - pose(keys[i - 1]));
}

// The pose at time t within keys a = keys[i], b = keys[i + 1], s = (t - a.frame) / h in [0, 1].
Pose segment_pose(const CameraPath& path, size_t i, double s) {
  const std::vector<CameraKey>& keys = path.keys;
  if (path.interpolation == CameraPath::Interpolation::Linear)
    return pose(keys[i]) + s * (pose(keys[i + 1]) - pose(keys[i]));
  // Cubic Hermite in time with velocities m_i: p = h00 p_a + h10 h m_a + h01 p_b + h11 h m_b. Both
  // segments meeting at a key share its pose and velocity, so the path is C1 in time.
  const double h = keys[i + 1].frame - keys[i].frame;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s;
  const double h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
  return h00 * pose(keys[i]) + (h10 * h) * key_velocity(keys, i) + h01 * pose(keys[i + 1]) +
         (h11 * h) * key_velocity(keys, i + 1);
}

}  // namespace

const char* camera_defect(const Camera& camera) {
  const glm::dvec3 view = camera.target - camera.position;
  if (!(glm::length(view) > 1e-12 * std::max(1.0, glm::length(camera.position)))) return "target";
  // sin of the angle between up and the view direction; 1e-6 rad leaves a usable basis.
  const double sin_angle = glm::length(glm::cross(glm::normalize(view), glm::normalize(camera.up)));
  return sin_angle > 1e-6 ? nullptr : "up";
}

CameraPath read_camera_path(JsonObjectReader r, const Camera& camera) {
  CameraPath path;
  path.frames = r.integer_in("frames", 1, kMaxPathFrames);
  const std::string interpolation = r.string("interpolation", std::string("linear"));
  if (interpolation == "smooth") {
    path.interpolation = CameraPath::Interpolation::Smooth;
  } else if (interpolation != "linear") {
    r.fail("interpolation", "must be linear or smooth");
  }
  const nlohmann::json& keys = r.value("keys");
  if (!keys.is_array() || keys.empty()) r.fail("keys", "must be a non-empty array of keyframes");
  for (size_t i = 0; i < keys.size(); ++i) {
    JsonObjectReader k(keys[i], r.file(), r.key_path("keys") + "[" + std::to_string(i) + "]");
    CameraKey key;
    key.frame = k.integer_in("frame", 0, path.frames - 1);
    if (!path.keys.empty() && key.frame <= path.keys.back().frame)
      k.fail("frame", "must be greater than the previous key's frame");
    key.position = k.vec3("position");
    key.target = k.vec3("target");
    key.fov_y_deg = k.number("fov_y", camera.fov_y_deg);
    if (!(key.fov_y_deg > 0.0 && key.fov_y_deg < 180.0)) k.fail("fov_y", "must be in (0, 180) degrees");
    k.finish();
    path.keys.push_back(key);
  }
  r.finish();
  // The smooth path can overshoot its keys, so every frame is checked, not only the keys.
  for (int frame = 0; frame < path.frames; ++frame) {
    const Camera c = camera_on_path(path, camera, frame);
    const std::string where = r.file() + ": " + r.path() + ": frame " + std::to_string(frame);
    if (!(c.fov_y_deg > 0.0 && c.fov_y_deg < 180.0))
      throw Error(where + " has fov_y " + std::to_string(c.fov_y_deg) + ", outside (0, 180) degrees");
    if (const char* defect = camera_defect(c))
      throw Error(where +
                  (defect == std::string("target") ? " has its target at its position" : " looks along camera.up"));
  }
  return path;
}

Camera camera_on_path(const CameraPath& path, const Camera& base, double t) {
  const std::vector<CameraKey>& keys = path.keys;
  // The segment [keys[i], keys[i + 1]] holding t; outside the keys, the nearest key's pose.
  Pose p = pose(t <= keys.front().frame ? keys.front() : keys.back());
  if (t > keys.front().frame && t < keys.back().frame) {
    const auto after = std::upper_bound(keys.begin(), keys.end(), t,
                                        [](double time, const CameraKey& key) { return time < key.frame; });
    const size_t i = static_cast<size_t>(after - keys.begin()) - 1;
    p = segment_pose(path, i, (t - keys[i].frame) / (keys[i + 1].frame - keys[i].frame));
  }
  Camera camera = base;
  camera.position = p.position;
  camera.target = p.target;
  camera.fov_y_deg = p.fov_y_deg;
  return camera;
}

int frame_count(const Scene& scene) { return scene.camera_path ? scene.camera_path->frames : 1; }

Camera camera_at(const Scene& scene, int frame) {
  if (frame < 0 || frame >= frame_count(scene))
    throw Error(scene.source.string() + ": frame " + std::to_string(frame) + " is outside [0, " +
                std::to_string(frame_count(scene) - 1) + "]" +
                (scene.camera_path ? "" : " (the scene has no camera_path)"));
  return scene.camera_path ? camera_on_path(*scene.camera_path, scene.camera, frame) : scene.camera;
}

}  // namespace facet
