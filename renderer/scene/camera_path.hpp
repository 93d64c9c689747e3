// Camera paths: keyframed position, target and field of view over a numbered sequence of frames,
// so one scene file describes an animation (scenes/README.md, `camera_path`; docs/batch.md).
#pragma once

#include "common/json_object_reader.hpp"
#include "scene/scene.hpp"

namespace facet {

inline constexpr int kMaxPathFrames = 1000000;

// Why `camera` has no view basis: "target" (target == position) or "up" (up parallel to the view
// direction), naming the key to blame; nullptr when the camera is usable.
const char* camera_defect(const Camera& camera);

// Reads the "camera_path" object; `camera` is the scene's camera, whose fov_y is each key's default.
// Every frame's camera is checked, so a path through a degenerate pose is an error at load time.
CameraPath read_camera_path(JsonObjectReader r, const Camera& camera);

// `base` with the pose of `path` at frame time `t` (fractional times lie between frames); before the
// first key and after the last the camera holds still.
Camera camera_on_path(const CameraPath& path, const Camera& base, double t);

// How many frames the scene has: the path's, or 1 (the still `camera`).
int frame_count(const Scene& scene);

// The camera of frame `frame` in [0, frame_count(scene)); throws facet::Error outside.
Camera camera_at(const Scene& scene, int frame);

}  // namespace facet
