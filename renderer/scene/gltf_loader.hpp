// Loads the triangle meshes of a glTF 2.0 file (.gltf with embedded or external buffers, or .glb).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet {

// Walks the default scene's node hierarchy (scene 0 if none is marked default, every root
// node if the file has no scenes) and returns one Mesh per triangle primitive instance,
// in world space: object_to_world * (node transforms). Reads POSITION, NORMAL, TEXCOORD_0
// and TANGENT (kept only with NORMAL, as glTF requires) and indices of any integer type.
// Every mesh gets `material`. Throws facet::Error "<file>: <what>" for anything invalid:
// non-triangle modes, out-of-range indices, accessors outside their buffers, non-finite
// attributes, singular transforms, node cycles, required extensions.
std::vector<Mesh> load_gltf_meshes(const std::filesystem::path& file, const glm::dmat4& object_to_world,
                                   uint32_t material);

}  // namespace facet
