// Reads a whole glTF 2.0 scene (.gltf or .glb) as a facet scene (scenes/README.md, "glTF scenes"):
// its first perspective camera, its KHR_lights_punctual directional light, the camera node's
// animation as a camera_path, every mesh node, and facet materials from the glTF materials'
// `extras.facet` blocks.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace facet {

inline constexpr double kDefaultGltfFps = 24.0;  // frames per second of a sampled camera animation
inline constexpr int kDefaultGltfHeight = 360;   // image height; the width keeps the camera's aspect
// Frames of a sampled camera animation (7 minutes at 24 fps): each is a key of the path, so a stray key
// time in a file must not allocate a million of them.
inline constexpr int kMaxGltfPathFrames = 10000;

// The camera, light, camera_path, materials, ambient and background become a facet JSON scene
// document, to which `overrides` apply ("camera.width=320") and which parse_scene() validates as any
// scene file; the meshes are added after. Every problem is a one-line facet::Error naming `file`.
Scene load_gltf_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides);

}  // namespace facet
