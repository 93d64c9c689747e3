#include "scene/gltf_loader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <utility>

#include <tiny_gltf.h>
#include <glm/gtc/quaternion.hpp>

#include "common/error.hpp"
#include "scene/gltf_accessor.hpp"
#include "scene/gltf_model.hpp"
#include "scene/mesh_check.hpp"
#include "scene/transform.hpp"

namespace facet {

namespace {

// facet renders no textures: skip decoding embedded images instead of failing on them.
bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

template <glm::length_t N>
bool all_finite(const glm::vec<N, double>& v) {
  for (glm::length_t i = 0; i < N; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

std::string one_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ';';
  }
  return text;
}

// glTF JSON is nested a handful of levels; tinygltf walks `extras` recursively, so a deeply
// nested document would overflow the stack there. Counted outside strings.
constexpr int kMaxGltfJsonDepth = 64;

int json_nesting_depth(std::string_view json) {
  int depth = 0, max_depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : json) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      max_depth = std::max(max_depth, ++depth);
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return max_depth;
}

// The JSON chunk of a .glb (glTF 2.0 §4.4: 12-byte header, then chunk length, type "JSON");
// empty if the header is malformed, which tinygltf then reports.
std::string_view glb_json_chunk(const std::string& bytes) {
  if (bytes.size() < 20) return {};
  uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return std::string_view(bytes).substr(20, length);
}

}  // namespace

tinygltf::Model load_gltf_model(const std::filesystem::path& file, const std::set<std::string>& understood_extensions) {
  const std::string extension = file.extension().string();
  if (extension != ".gltf" && extension != ".glb") throw Error("mesh files must end in .gltf or .glb");
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || !std::filesystem::is_regular_file(file, ec)) throw Error("cannot open (no such file)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) throw Error("file is larger than 4 GiB");
  const bool binary = extension == ".glb";
  if (json_nesting_depth(binary ? glb_json_chunk(bytes) : std::string_view(bytes)) > kMaxGltfJsonDepth) {
    throw Error("invalid glTF: JSON nested deeper than " + std::to_string(kMaxGltfJsonDepth) + " levels");
  }

  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(ignore_image, nullptr);
  loader.SetStoreOriginalJSONForExtrasAndExtensions(true);  // extras as JSON text (gltf_scene.cpp)
  tinygltf::Model model;
  std::string err, warn;
  const std::string base_dir = file.parent_path().string();  // for external buffers
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary
                      ? loader.LoadBinaryFromMemory(
                            &model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()), size, base_dir)
                      : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, base_dir);
  if (!ok) throw Error("invalid glTF: " + one_line(err.empty() ? std::string("unknown error") : err));
  std::string names;
  for (const std::string& n : model.extensionsRequired)
    if (!understood_extensions.count(n)) names += (names.empty() ? "" : ", ") + n;
  if (!names.empty()) throw Error("requires unsupported glTF extensions: " + names);
  return model;
}

glm::dmat4 gltf_local_transform(const tinygltf::Node& node, size_t index) {
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16) throw Error("node " + std::to_string(index) + ": matrix needs 16 numbers");
    glm::dmat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = node.matrix[static_cast<size_t>(i)];  // column-major
    return m;
  }
  glm::dmat4 m(1.0);
  if (node.translation.size() == 3) {
    m[3] = glm::dvec4(node.translation[0], node.translation[1], node.translation[2], 1.0);
  }
  if (node.rotation.size() == 4) {  // glTF quaternions are (x, y, z, w), glm's constructor takes w first
    const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    const double norm = glm::length(q);
    if (!(norm > 0.0) || !std::isfinite(norm)) {
      throw Error("node " + std::to_string(index) + ": rotation is not a valid quaternion");
    }
    m = m * glm::dmat4(glm::mat3_cast(q / norm));
  }
  if (node.scale.size() == 3) {
    m = m * glm::dmat4(glm::dmat3(node.scale[0], 0, 0, 0, node.scale[1], 0, 0, 0, node.scale[2]));
  }
  return m;
}

namespace {

// Attribute `key` as vectors of N finite components, one per vertex (`vertex_count`, unless
// this is POSITION, which defines it); empty if the primitive does not have it.
template <glm::length_t N>
std::vector<glm::vec<N, double>> read_attribute(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                                const char* key, const std::string& name, size_t vertex_count) {
  const auto it = primitive.attributes.find(key);
  if (it == primitive.attributes.end()) return {};
  constexpr int kType = N == 2 ? TINYGLTF_TYPE_VEC2 : N == 3 ? TINYGLTF_TYPE_VEC3 : TINYGLTF_TYPE_VEC4;
  const std::string what = name + " " + key;
  const AccessorData a = read_accessor(model, it->second, kType, false, what);
  if (std::string(key) != "POSITION" && a.count != vertex_count) {
    throw Error(what + ": has " + std::to_string(a.count) + " elements, POSITION has " + std::to_string(vertex_count));
  }
  std::vector<glm::vec<N, double>> out(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    for (glm::length_t c = 0; c < N; ++c) out[i][c] = a.values[N * i + static_cast<size_t>(c)];
    if (!all_finite(out[i])) throw Error(what + ": element " + std::to_string(i) + " is not finite");
  }
  return out;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                   const std::string& name, size_t vertex_count) {
  std::vector<uint32_t> indices;
  if (primitive.indices < 0) {  // non-indexed: consecutive vertex triples
    for (size_t i = 0; i < vertex_count; ++i) indices.push_back(static_cast<uint32_t>(i));
    return indices;
  }
  const AccessorData a = read_accessor(model, primitive.indices, TINYGLTF_TYPE_SCALAR, true, name + " indices");
  indices.reserve(a.count);
  for (size_t i = 0; i < a.count; ++i) {
    const double index = a.values[i];
    if (index < 0.0 || index >= static_cast<double>(vertex_count)) {
      throw Error(name + " indices: index " + std::to_string(i) + " = " +
                  std::to_string(static_cast<long long>(index)) + " is outside [0, " + std::to_string(vertex_count) +
                  ")");
    }
    indices.push_back(static_cast<uint32_t>(index));
  }
  return indices;
}

Mesh read_primitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
    throw Error(name + ": mode " + std::to_string(primitive.mode) + " is not supported (only triangles, mode 4)");
  }
  Mesh mesh;
  mesh.name = name;
  mesh.positions = read_attribute<3>(model, primitive, "POSITION", name, 0);
  const size_t n = mesh.positions.size();
  if (n == 0) throw Error(name + ": has no POSITION attribute");
  if (n > std::numeric_limits<uint32_t>::max()) throw Error(name + ": too many vertices");

  mesh.normals = read_attribute<3>(model, primitive, "NORMAL", name, n);
  for (size_t i = 0; i < mesh.normals.size(); ++i) {
    if (!(glm::length(mesh.normals[i]) > 1e-30))
      throw Error(name + " NORMAL: normal " + std::to_string(i) + " is zero");
    mesh.normals[i] = glm::normalize(mesh.normals[i]);
  }
  mesh.uvs = read_attribute<2>(model, primitive, "TEXCOORD_0", name, n);
  // glTF 2.0 §3.7.2.1: without normals, supplied tangents must be ignored.
  if (!mesh.normals.empty()) mesh.tangents = read_attribute<4>(model, primitive, "TANGENT", name, n);
  for (size_t i = 0; i < mesh.tangents.size(); ++i) {
    const glm::dvec4 t = mesh.tangents[i];
    if (!(glm::length(glm::dvec3(t)) > 1e-30) || t.w == 0.0) {
      throw Error(name + " TANGENT: tangent " + std::to_string(i) + " is zero or has w = 0");
    }
    mesh.tangents[i] = glm::dvec4(glm::normalize(glm::dvec3(t)), t.w > 0.0 ? 1.0 : -1.0);
  }

  mesh.indices = read_indices(model, primitive, name, n);
  if (mesh.indices.size() % 3 != 0) {
    throw Error(name + ": " + std::to_string(mesh.indices.size()) + " indices is not a whole number of triangles");
  }
  return mesh;
}

}  // namespace

void for_each_gltf_node(const tinygltf::Model& model, const glm::dmat4& root_to_world,
                        const std::function<void(size_t, const glm::dmat4&)>& visit) {
  std::vector<std::pair<int, glm::dmat4>> stack;  // (node, parent-to-world); explicit, cycles are checked
  if (!model.scenes.empty()) {
    const size_t scene = model.defaultScene >= 0 ? static_cast<size_t>(model.defaultScene) : 0;
    if (scene >= model.scenes.size()) throw Error("default scene " + std::to_string(scene) + " does not exist");
    for (int root : model.scenes[scene].nodes) stack.emplace_back(root, root_to_world);
  } else {
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
      for (int c : node.children) {
        if (c >= 0 && static_cast<size_t>(c) < is_child.size()) is_child[static_cast<size_t>(c)] = true;
      }
    }
    for (size_t i = 0; i < model.nodes.size(); ++i) {
      if (!is_child[i]) stack.emplace_back(static_cast<int>(i), root_to_world);
    }
  }

  std::vector<bool> visited(model.nodes.size(), false);
  while (!stack.empty()) {
    const auto [index, parent] = stack.back();
    stack.pop_back();
    if (index < 0 || static_cast<size_t>(index) >= model.nodes.size()) {
      throw Error("node " + std::to_string(index) + " does not exist");
    }
    const size_t node_index = static_cast<size_t>(index);
    // glTF 2.0 §3.5.3: the hierarchy is a set of disjoint trees.
    if (visited[node_index]) throw Error("node " + std::to_string(index) + " is reached twice (cycle or shared child)");
    visited[node_index] = true;
    const tinygltf::Node& node = model.nodes[node_index];
    const glm::dmat4 world = parent * gltf_local_transform(node, node_index);
    for (int child : node.children) stack.emplace_back(child, world);
    visit(node_index, world);
  }
}

std::vector<Mesh> read_gltf_node_meshes(const tinygltf::Model& model, size_t node_index, const glm::dmat4& world,
                                        const std::function<uint32_t(int)>& material_of) {
  const tinygltf::Node& node = model.nodes[node_index];
  std::vector<Mesh> meshes;
  if (node.mesh < 0) return meshes;
  if (static_cast<size_t>(node.mesh) >= model.meshes.size()) {
    throw Error("node " + std::to_string(node_index) + " references missing mesh " + std::to_string(node.mesh));
  }
  const tinygltf::Mesh& gltf_mesh = model.meshes[static_cast<size_t>(node.mesh)];
  for (size_t p = 0; p < gltf_mesh.primitives.size(); ++p) {
    const std::string name = (gltf_mesh.name.empty() ? "mesh " + std::to_string(node.mesh) : gltf_mesh.name) +
                             " primitive " + std::to_string(p);
    Mesh mesh = read_primitive(model, gltf_mesh.primitives[p], name);
    try {
      transform_mesh(mesh, world);
    } catch (const Error& e) {
      throw Error("node " + std::to_string(node_index) + ": " + e.what());
    }
    check_mesh(mesh);  // e.g. a transform that overflows the float range
    mesh.material = material_of(gltf_mesh.primitives[p].material);
    meshes.push_back(std::move(mesh));
  }
  return meshes;
}

void rethrow_as_gltf_error(const std::filesystem::path& file) {
  try {
    throw;
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  } catch (const std::exception& e) {  // tinygltf or the allocator; keep the one-line contract
    throw Error(file.string() + ": cannot load glTF: " + one_line(e.what()));
  }
}

std::vector<Mesh> load_gltf_meshes(const std::filesystem::path& file, const glm::dmat4& object_to_world,
                                   uint32_t material) {
  try {
    const tinygltf::Model model = load_gltf_model(file);
    std::vector<Mesh> meshes;
    for_each_gltf_node(model, object_to_world, [&](size_t node, const glm::dmat4& world) {
      for (Mesh& m : read_gltf_node_meshes(model, node, world, [&](int) { return material; }))
        meshes.push_back(std::move(m));
    });
    return meshes;
  } catch (const std::exception&) {
    rethrow_as_gltf_error(file);
  }
}

}  // namespace facet
