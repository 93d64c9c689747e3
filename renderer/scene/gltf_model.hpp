// The pieces of glTF reading that load_gltf_meshes() (gltf_loader.hpp) is made of, shared with the
// scene reader (gltf_scene.hpp). They throw facet::Error without the file name;
// rethrow_as_gltf_error() adds it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

#include "scene/scene.hpp"

namespace facet {

// Parses `file` (.gltf or .glb), skipping images. Extensions in extensionsRequired must be among
// `understood_extensions`.
tinygltf::Model load_gltf_model(const std::filesystem::path& file,
                                const std::set<std::string>& understood_extensions = {});

// A node's local transform: its matrix, or T * R * S (glTF 2.0 §3.5.3).
glm::dmat4 gltf_local_transform(const tinygltf::Node& node, size_t index);

// Calls visit(node, node-to-world) for every node of the default scene (see load_gltf_meshes),
// a parent before its children; rejects missing nodes and cycles.
void for_each_gltf_node(const tinygltf::Model& model, const glm::dmat4& root_to_world,
                        const std::function<void(size_t, const glm::dmat4&)>& visit);

// The triangle primitives of node `node` in world space, each with material_of(its glTF material
// index, -1 for none).
std::vector<Mesh> read_gltf_node_meshes(const tinygltf::Model& model, size_t node, const glm::dmat4& world,
                                        const std::function<uint32_t(int)>& material_of);

// Inside a catch block: rethrows the exception in flight as one-line facet::Error "<file>: <what>".
[[noreturn]] void rethrow_as_gltf_error(const std::filesystem::path& file);

}  // namespace facet
