// Camera paths: keys are hit exactly, linear is linear, smooth is C1 at every key (and linear is
// not, so the C1 check can fail), every frame is validated on load.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "scene/camera_path.hpp"
#include "scene/scene_loader.hpp"

namespace facet {
namespace camera_path_test {

using Json = nlohmann::json;

// Keys at uneven spacing (0, 10, 35, 40) so the Catmull-Rom velocities are not symmetric.
Json path_json(const std::string& interpolation) {
  return Json::parse(R"({"frames": 41, "interpolation": ")" + interpolation + R"(", "keys": [
    {"frame": 0,  "position": [0, 6, 2],   "target": [0, 0, -1], "fov_y": 60},
    {"frame": 10, "position": [1.5, 2, 1], "target": [0, 0, -4], "fov_y": 75},
    {"frame": 35, "position": [-1, 1, 3], "target": [1, 0, -6]},
    {"frame": 40, "position": [0, 0.25, 1], "target": [0, 0.05, -8], "fov_y": 88}]})");
}

Scene scene_with_path(const std::string& interpolation) {
  Json scene = {{"camera", {{"position", {0, 1, 0}}, {"target", {0, 0, -1}}, {"fov_y", 50}}}};
  scene["camera_path"] = path_json(interpolation);
  return parse_scene(scene, "path.json");
}

// Position, target and fov stacked as 7 numbers.
std::array<double, 7> pose(const Camera& c) {
  return {c.position.x, c.position.y, c.position.z, c.target.x, c.target.y, c.target.z, c.fov_y_deg};
}

std::array<double, 7> pose_at(const Scene& scene, double t) {
  return pose(camera_on_path(*scene.camera_path, scene.camera, t));
}

TEST(CameraPath, KeysAreHitExactlyAndFovDefaultsToTheCamera) {
  for (const char* interpolation : {"linear", "smooth"}) {
    const Scene scene = scene_with_path(interpolation);
    ASSERT_EQ(frame_count(scene), 41);
    for (const CameraKey& key : scene.camera_path->keys) {
      const Camera c = camera_at(scene, key.frame);
      EXPECT_EQ(c.position, key.position) << interpolation << " frame " << key.frame;
      EXPECT_EQ(c.target, key.target) << interpolation << " frame " << key.frame;
      EXPECT_EQ(c.fov_y_deg, key.fov_y_deg) << interpolation << " frame " << key.frame;
      EXPECT_EQ(c.width, scene.camera.width);  // up and size come from `camera`
      EXPECT_EQ(c.up, scene.camera.up);
    }
    EXPECT_EQ(scene.camera_path->keys[2].fov_y_deg, 50.0);
  }
}

TEST(CameraPath, LinearIsTheStraightLineBetweenKeys) {
  const Scene scene = scene_with_path("linear");
  const auto a = pose(camera_at(scene, 10)), b = pose(camera_at(scene, 35));
  for (int frame = 10; frame <= 35; ++frame) {
    const auto p = pose(camera_at(scene, frame));
    const double s = (frame - 10) / 25.0;
    for (int k = 0; k < 7; ++k) EXPECT_NEAR(p[k], a[k] + s * (b[k] - a[k]), 1e-13 * (1 + std::abs(b[k]))) << frame;
  }
}

// Left and right derivatives at time t by second-order one-sided differences, step e:
// f'(t) ≈ ±(3 f(t) - 4 f(t ∓ e) + f(t ∓ 2e)) / (2e), error O(e²).
double kink(const Scene& scene, double t, int k, double e) {
  const double left =
      (3 * pose_at(scene, t)[k] - 4 * pose_at(scene, t - e)[k] + pose_at(scene, t - 2 * e)[k]) / (2 * e);
  const double right =
      -(3 * pose_at(scene, t)[k] - 4 * pose_at(scene, t + e)[k] + pose_at(scene, t + 2 * e)[k]) / (2 * e);
  return std::abs(left - right);
}

TEST(CameraPath, SmoothIsC1AtEveryKeyWhereLinearIsNot) {
  const Scene smooth = scene_with_path("smooth"), linear = scene_with_path("linear");
  // One-sided second-order differences err by e²/3 · |f'''|. On a Hermite segment
  // |f'''| <= (12 |Δp| + 6 h (|m_a| + |m_b|)) / h³, largest for fov on frames 35-40 (Δ 38, h 5): 3.8
  // per frame³, so e = 1e-4 gives 1.3e-8; rounding adds ~1e-16 · 88 · 8 / (2e) ≈ 4e-10. Tolerance 1e-7.
  const double e = 1e-4, tolerance = 1e-7;
  double worst = 0.0;
  for (int key : {10, 35})
    for (int k = 0; k < 7; ++k) worst = std::max(worst, kink(smooth, key, k, e));
  EXPECT_LT(worst, tolerance);
  // The same measure sees the linear path bend: x changes slope from 0.15 to -0.1 per frame at frame 10.
  EXPECT_NEAR(kink(linear, 10, 0, e), 0.25, 1e-9);
}

TEST(CameraPath, SmoothVelocitiesAreCatmullRomInsideAndZeroAtTheEnds) {
  const Scene smooth = scene_with_path("smooth");
  const double e = 1e-4;  // error bound as in SmoothIsC1AtEveryKeyWhereLinearIsNot
  const auto right_derivative = [&](double t, int k) {
    return -(3 * pose_at(smooth, t)[k] - 4 * pose_at(smooth, t + e)[k] + pose_at(smooth, t + 2 * e)[k]) / (2 * e);
  };
  const auto p0 = pose(camera_at(smooth, 0)), p10 = pose(camera_at(smooth, 10)), p35 = pose(camera_at(smooth, 35)),
             p40 = pose(camera_at(smooth, 40));
  for (int k = 0; k < 7; ++k) {
    EXPECT_NEAR(right_derivative(10, k), (p35[k] - p0[k]) / 35.0, 1e-7) << k;
    EXPECT_NEAR(right_derivative(35, k), (p40[k] - p10[k]) / 30.0, 1e-7) << k;
    EXPECT_NEAR(right_derivative(0, k), 0.0, 1e-7) << k;
  }
}

TEST(CameraPath, HoldsStillOutsideTheKeys) {
  Json scene = {{"camera_path", Json::parse(R"({"frames": 10, "keys": [
      {"frame": 3, "position": [0, 2, 2], "target": [0, 0, 0]}, {"frame": 6, "position": [0, 3, 3], "target": [0, 0, 0]}]})")}};
  const Scene s = parse_scene(scene, "hold.json");
  EXPECT_EQ(camera_at(s, 0).position, glm::dvec3(0, 2, 2));
  EXPECT_EQ(camera_at(s, 9).position, glm::dvec3(0, 3, 3));
  EXPECT_EQ(camera_at(s, 9).fov_y_deg, s.camera.fov_y_deg);
}

TEST(CameraPath, WithoutAPathTheSceneHasOneFrame) {
  const Scene s = parse_scene(Json::object(), "still.json");
  EXPECT_EQ(frame_count(s), 1);
  EXPECT_EQ(camera_at(s, 0).position, s.camera.position);
  EXPECT_THROW(camera_at(s, 1), Error);
  EXPECT_THROW(camera_at(s, -1), Error);
  EXPECT_THROW(camera_at(scene_with_path("smooth"), 41), Error);
}

std::string load_error(const std::string& path) {
  try {
    parse_scene(Json{{"camera_path", Json::parse(path)}}, "bad.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(CameraPath, BadPathsAreOneLineErrors) {
  const std::string key_a = R"({"frame": 0, "position": [0, 1, 2], "target": [0, 0, 0]})";
  EXPECT_EQ(load_error(R"({"frames": 0, "keys": [)" + key_a + "]}"),
            "bad.json: camera_path.frames must be an integer in [1, 1000000], got 0");
  EXPECT_EQ(load_error(R"({"frames": 5, "keys": []})"),
            "bad.json: camera_path.keys must be a non-empty array of keyframes, got []");
  EXPECT_EQ(load_error(R"({"frames": 5, "interpolation": "cubic", "keys": [)" + key_a + "]}"),
            "bad.json: camera_path.interpolation must be linear or smooth, got \"cubic\"");
  EXPECT_EQ(load_error(R"({"frames": 5, "keys": [)" + key_a + "," + key_a + "]}"),
            "bad.json: camera_path.keys[1].frame must be greater than the previous key's frame, got 0");
  EXPECT_EQ(load_error(R"({"frames": 5, "keys": [{"frame": 5, "position": [0, 1, 2], "target": [0, 0, 0]}]})"),
            "bad.json: camera_path.keys[0].frame must be an integer in [0, 4], got 5");
  EXPECT_NE(load_error(R"({"frames": 5, "keys": [{"frame": 0, "position": [0, 1, 2], "target": [0, 0, 0], "fov": 3}]})")
                .find("unknown key \"fov\" in camera_path.keys[0]"),
            std::string::npos);
  // Position and target swap places: at frame 2 they meet.
  EXPECT_EQ(load_error(R"({"frames": 5, "keys": [{"frame": 0, "position": [0, 1, 0], "target": [0, 1, -2]},
                                                  {"frame": 4, "position": [0, 1, -2], "target": [0, 1, 0]}]})"),
            "bad.json: camera_path: frame 2 has its target at its position");
  // Looking straight down along up at frame 0.
  EXPECT_EQ(load_error(R"({"frames": 2, "keys": [{"frame": 0, "position": [0, 3, 0], "target": [0, 0, 0]}]})"),
            "bad.json: camera_path: frame 0 looks along camera.up");
  // fov 10 -> 179 -> 179 smooth: the Catmull-Rom velocity at the middle key carries it past 180.
  EXPECT_NE(load_error(R"({"frames": 21, "interpolation": "smooth", "keys": [
      {"frame": 0, "position": [0, 1, 2], "target": [0, 0, 0], "fov_y": 10},
      {"frame": 10, "position": [0, 1, 2], "target": [0, 0, 0], "fov_y": 179},
      {"frame": 20, "position": [0, 1, 2], "target": [0, 0, 0], "fov_y": 179}]})")
                .find("outside (0, 180) degrees"),
            std::string::npos);
}

}  // namespace camera_path_test
}  // namespace facet
