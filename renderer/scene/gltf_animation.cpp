#include "scene/gltf_animation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "common/error.hpp"
#include "scene/gltf_accessor.hpp"
#include "scene/gltf_model.hpp"

namespace facet {

namespace {

GltfTrack read_track(const tinygltf::Model& model, const tinygltf::Animation& animation, size_t a,
                     const tinygltf::AnimationChannel& channel) {
  const std::string what = "animation " + std::to_string(a) + " channel " + channel.target_path;
  if (channel.sampler < 0 || static_cast<size_t>(channel.sampler) >= animation.samplers.size())
    throw Error(what + ": sampler " + std::to_string(channel.sampler) + " does not exist");
  const tinygltf::AnimationSampler& sampler = animation.samplers[static_cast<size_t>(channel.sampler)];
  GltfTrack track;
  if (sampler.interpolation == "STEP") {
    track.interpolation = GltfTrack::Interpolation::Step;
  } else if (sampler.interpolation != "LINEAR") {
    throw Error(what + ": interpolation " + sampler.interpolation + " is not supported (only LINEAR and STEP)");
  }
  const bool rotation = channel.target_path == "rotation";
  const AccessorData input = read_accessor(model, sampler.input, TINYGLTF_TYPE_SCALAR, false, what + " input");
  const AccessorData output =
      read_accessor(model, sampler.output, rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3, false, what + " output");
  if (output.count != input.count)
    throw Error(what + ": has " + std::to_string(input.count) + " key times but " + std::to_string(output.count) +
                " values");
  track.times = input.values;
  for (size_t i = 0; i < input.count; ++i) {
    if (!std::isfinite(track.times[i]) || (i > 0 && !(track.times[i] > track.times[i - 1])))
      throw Error(what + ": key time " + std::to_string(i) + " is not finite or not after the previous one");
    glm::dvec4 v(0.0);
    for (int c = 0; c < output.components; ++c) v[c] = output.values[static_cast<size_t>(output.components) * i + c];
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z) || !std::isfinite(v.w))
      throw Error(what + ": value " + std::to_string(i) + " is not finite");
    if (rotation) {
      if (!(glm::length(v) > 0.0)) throw Error(what + ": value " + std::to_string(i) + " is not a valid quaternion");
      v = glm::normalize(v);
    }
    track.values.push_back(v);
  }
  return track;
}

}  // namespace

std::optional<GltfNodeAnimation> read_gltf_node_animation(const tinygltf::Model& model, size_t node) {
  for (size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& animation = model.animations[a];
    GltfNodeAnimation result;
    result.animation = a;
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
      if (channel.target_node < 0 || static_cast<size_t>(channel.target_node) != node) continue;
      std::optional<GltfTrack>* slot = channel.target_path == "translation" ? &result.translation
                                       : channel.target_path == "rotation"  ? &result.rotation
                                       : channel.target_path == "scale"     ? &result.scale
                                                                            : nullptr;
      if (slot == nullptr) continue;  // morph weights do not move the node
      if (slot->has_value())
        throw Error("animation " + std::to_string(a) + " has two " + channel.target_path + " channels for node " +
                    std::to_string(node));
      *slot = read_track(model, animation, a, channel);
    }
    bool first = true;
    for (const auto* track : {&result.translation, &result.rotation, &result.scale}) {
      if (!track->has_value()) continue;
      result.start = first ? (*track)->times.front() : std::min(result.start, (*track)->times.front());
      result.end = first ? (*track)->times.back() : std::max(result.end, (*track)->times.back());
      first = false;
    }
    if (first) continue;
    if (!model.nodes[node].matrix.empty())
      throw Error("node " + std::to_string(node) + " is animated but has a matrix (glTF 2.0 §3.11 forbids it)");
    return result;
  }
  return std::nullopt;
}

glm::dvec4 sample_gltf_track(const GltfTrack& track, bool rotation, double t) {
  const std::vector<double>& times = track.times;
  if (t <= times.front()) return track.values.front();
  if (t >= times.back()) return track.values.back();
  const size_t i = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
  if (track.interpolation == GltfTrack::Interpolation::Step) return track.values[i];
  const double s = (t - times[i]) / (times[i + 1] - times[i]);
  const glm::dvec4 a = track.values[i], b = track.values[i + 1];
  if (!rotation) return a + s * (b - a);
  // glm's quaternions take w first; its slerp goes along the shorter arc.
  const glm::dquat q = glm::slerp(glm::dquat(a.w, a.x, a.y, a.z), glm::dquat(b.w, b.x, b.y, b.z), s);
  return glm::dvec4(q.x, q.y, q.z, q.w);
}

glm::dmat4 animated_local_transform(const tinygltf::Node& node, size_t index, const GltfNodeAnimation& animation,
                                    double t) {
  tinygltf::Node posed = node;
  const auto assign = [&](const std::optional<GltfTrack>& track, std::vector<double>& target, bool rotation) {
    if (!track) return;
    const glm::dvec4 v = sample_gltf_track(*track, rotation, t);
    target.assign({v.x, v.y, v.z});
    if (rotation) target.push_back(v.w);
  };
  assign(animation.translation, posed.translation, false);
  assign(animation.rotation, posed.rotation, true);
  assign(animation.scale, posed.scale, false);
  return gltf_local_transform(posed, index);
}

}  // namespace facet
