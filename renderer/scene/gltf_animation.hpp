// Node animation of glTF 2.0 (§3.11): the translation, rotation and scale channels of one node,
// sampled at any time, for the camera paths of glTF scenes (gltf_scene.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

namespace facet {

// One channel's keyframes: times in seconds, strictly increasing; values xyz (translation, scale)
// or xyzw (rotation, a unit quaternion in glTF's order).
struct GltfTrack {
  enum class Interpolation { Linear, Step };
  Interpolation interpolation = Interpolation::Linear;
  std::vector<double> times;
  std::vector<glm::dvec4> values;
};

struct GltfNodeAnimation {
  size_t animation = 0;  // its index in the file
  std::optional<GltfTrack> translation, rotation, scale;
  double start = 0.0, end = 0.0;  // the first and last key time over the tracks
};

// The channels of the first animation that moves `node` (translation, rotation or scale), or
// nullopt if none does. Throws facet::Error for CUBICSPLINE samplers, keys out of order, non-finite
// values, or a node that is animated while it has a matrix (glTF 2.0 §3.11 forbids it).
std::optional<GltfNodeAnimation> read_gltf_node_animation(const tinygltf::Model& model, size_t node);

// The value of `track` at time t: the first or last key outside the keys; between two keys, linear
// interpolation, slerp along the shorter arc for rotations (glTF 2.0 Appendix C), or the earlier key
// for STEP.
glm::dvec4 sample_gltf_track(const GltfTrack& track, bool rotation, double t);

// The node's local transform at time t: its own translation, rotation and scale where no track of
// `animation` replaces them.
glm::dmat4 animated_local_transform(const tinygltf::Node& node, size_t index, const GltfNodeAnimation& animation,
                                    double t);

}  // namespace facet
