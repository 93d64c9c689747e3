// Loads and validates a facet scene file (format: scenes/README.md).
//
// Every problem is a facet::Error with one line naming the file and the offending key,
// e.g. "scenes/x.json: camera.width must be an integer in [1, 16384], got -4".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.hpp"

namespace facet {

inline constexpr int kMaxImageSide = 16384;
inline constexpr int kMaxJsonDepth = 64;

// Reads and parses `file`, applies `overrides` ("camera.width=320", common/json_overrides.hpp) in
// order, then validates; mesh paths are relative to its directory. A file ending in .gltf or .glb is
// read as a glTF 2.0 scene (gltf_scene.hpp).
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});

// Validates an already parsed document; `source` names it in messages and anchors
// relative mesh paths (an empty source means the current directory).
Scene parse_scene(const nlohmann::json& document, const std::filesystem::path& source);

}  // namespace facet
