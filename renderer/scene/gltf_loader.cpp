#include "scene/gltf_loader.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "common/error.hpp"
#include "scene/gltf_accessor.hpp"
#include "scene/mesh_check.hpp"
#include "scene/transform.hpp"

namespace facet {

namespace {

// facet renders no textures: skip decoding embedded images instead of failing on them.
bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*,
                  int, void*) {
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

tinygltf::Model load_model(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw Error("cannot open (no such file)");
  const std::string extension = file.extension().string();
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(ignore_image, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  if (extension == ".gltf") {
    ok = loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
  } else if (extension == ".glb") {
    ok = loader.LoadBinaryFromFile(&model, &err, &warn, file.string());
  } else {
    throw Error("mesh files must end in .gltf or .glb");
  }
  if (!ok) throw Error("invalid glTF: " + one_line(err.empty() ? std::string("unknown error") : err));
  if (!model.extensionsRequired.empty()) {
    std::string names;
    for (const std::string& n : model.extensionsRequired) names += (names.empty() ? "" : ", ") + n;
    throw Error("requires unsupported glTF extensions: " + names);
  }
  return model;
}

glm::dmat4 local_transform(const tinygltf::Node& node, size_t index) {
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

glm::dvec3 at3(const AccessorData& a, size_t i) {
  return {a.values[3 * i], a.values[3 * i + 1], a.values[3 * i + 2]};
}

Mesh read_primitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, const std::string& name) {
  if (primitive.mode != TINYGLTF_MODE_TRIANGLES) {
    throw Error(name + ": mode " + std::to_string(primitive.mode) + " is not supported (only triangles, mode 4)");
  }
  const auto attribute = [&](const char* key) {
    const auto it = primitive.attributes.find(key);
    return it == primitive.attributes.end() ? -1 : it->second;
  };
  const auto what = [&](const char* key) { return name + " " + key; };
  if (attribute("POSITION") < 0) throw Error(name + ": has no POSITION attribute");

  Mesh mesh;
  mesh.name = name;
  const AccessorData positions = read_accessor(model, attribute("POSITION"), TINYGLTF_TYPE_VEC3, false, what("POSITION"));
  const size_t n = positions.count;
  if (n > std::numeric_limits<uint32_t>::max()) throw Error(name + ": too many vertices");
  const auto check_count = [&](const AccessorData& a, const char* key) {
    if (a.count != n) throw Error(what(key) + ": has " + std::to_string(a.count) + " elements, POSITION has " + std::to_string(n));
  };
  for (size_t i = 0; i < n; ++i) {
    const glm::dvec3 p = at3(positions, i);
    if (!all_finite(p)) throw Error(what("POSITION") + ": vertex " + std::to_string(i) + " is not finite");
    mesh.positions.push_back(p);
  }
  if (attribute("NORMAL") >= 0) {
    const AccessorData normals = read_accessor(model, attribute("NORMAL"), TINYGLTF_TYPE_VEC3, false, what("NORMAL"));
    check_count(normals, "NORMAL");
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec3 v = at3(normals, i);
      if (!all_finite(v) || !(glm::length(v) > 1e-30)) {
        throw Error(what("NORMAL") + ": normal " + std::to_string(i) + " is zero or not finite");
      }
      mesh.normals.push_back(glm::normalize(v));
    }
  }
  if (attribute("TEXCOORD_0") >= 0) {
    const AccessorData uvs = read_accessor(model, attribute("TEXCOORD_0"), TINYGLTF_TYPE_VEC2, false, what("TEXCOORD_0"));
    check_count(uvs, "TEXCOORD_0");
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec2 uv(uvs.values[2 * i], uvs.values[2 * i + 1]);
      if (!all_finite(uv)) throw Error(what("TEXCOORD_0") + ": uv " + std::to_string(i) + " is not finite");
      mesh.uvs.push_back(uv);
    }
  }
  // glTF 2.0 §3.7.2.1: without normals, supplied tangents must be ignored.
  if (attribute("TANGENT") >= 0 && !mesh.normals.empty()) {
    const AccessorData tangents = read_accessor(model, attribute("TANGENT"), TINYGLTF_TYPE_VEC4, false, what("TANGENT"));
    check_count(tangents, "TANGENT");
    for (size_t i = 0; i < n; ++i) {
      const glm::dvec4 t(tangents.values[4 * i], tangents.values[4 * i + 1], tangents.values[4 * i + 2], tangents.values[4 * i + 3]);
      if (!all_finite(t) || !(glm::length(glm::dvec3(t)) > 1e-30) || t.w == 0.0) {
        throw Error(what("TANGENT") + ": tangent " + std::to_string(i) + " is zero, has w = 0 or is not finite");
      }
      mesh.tangents.emplace_back(glm::normalize(glm::dvec3(t)), t.w > 0.0 ? 1.0 : -1.0);
    }
  }

  if (primitive.indices >= 0) {
    const AccessorData indices = read_accessor(model, primitive.indices, TINYGLTF_TYPE_SCALAR, true, name + " indices");
    mesh.indices.reserve(indices.count);
    for (size_t i = 0; i < indices.count; ++i) {
      const double index = indices.values[i];
      if (index < 0.0 || index >= static_cast<double>(n)) {
        throw Error(name + " indices: index " + std::to_string(i) + " = " + std::to_string(static_cast<long long>(index)) +
                    " is outside [0, " + std::to_string(n) + ")");
      }
      mesh.indices.push_back(static_cast<uint32_t>(index));
    }
  } else {
    for (size_t i = 0; i < n; ++i) mesh.indices.push_back(static_cast<uint32_t>(i));
  }
  if (mesh.indices.size() % 3 != 0) {
    throw Error(name + ": " + std::to_string(mesh.indices.size()) + " indices is not a whole number of triangles");
  }
  return mesh;
}

}  // namespace

std::vector<Mesh> load_gltf_meshes(const std::filesystem::path& file, const glm::dmat4& object_to_world,
                                   uint32_t material) {
  try {
    const tinygltf::Model model = load_model(file);

    std::vector<std::pair<int, glm::dmat4>> stack;  // (node, parent-to-world); explicit, cycles are checked
    if (!model.scenes.empty()) {
      const size_t scene = model.defaultScene >= 0 ? static_cast<size_t>(model.defaultScene) : 0;
      if (scene >= model.scenes.size()) throw Error("default scene " + std::to_string(scene) + " does not exist");
      for (int root : model.scenes[scene].nodes) stack.emplace_back(root, object_to_world);
    } else {
      std::vector<bool> is_child(model.nodes.size(), false);
      for (const tinygltf::Node& node : model.nodes) {
        for (int c : node.children) {
          if (c >= 0 && static_cast<size_t>(c) < is_child.size()) is_child[static_cast<size_t>(c)] = true;
        }
      }
      for (size_t i = 0; i < model.nodes.size(); ++i) {
        if (!is_child[i]) stack.emplace_back(static_cast<int>(i), object_to_world);
      }
    }

    std::vector<Mesh> meshes;
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
      const glm::dmat4 world = parent * local_transform(node, node_index);
      for (int child : node.children) stack.emplace_back(child, world);
      if (node.mesh < 0) continue;
      if (static_cast<size_t>(node.mesh) >= model.meshes.size()) {
        throw Error("node " + std::to_string(index) + " references missing mesh " + std::to_string(node.mesh));
      }
      const tinygltf::Mesh& gltf_mesh = model.meshes[static_cast<size_t>(node.mesh)];
      for (size_t p = 0; p < gltf_mesh.primitives.size(); ++p) {
        const std::string name = (gltf_mesh.name.empty() ? "mesh " + std::to_string(node.mesh) : gltf_mesh.name) +
                                 " primitive " + std::to_string(p);
        Mesh mesh = read_primitive(model, gltf_mesh.primitives[p], name);
        try {
          transform_mesh(mesh, world);
        } catch (const Error& e) {
          throw Error("node " + std::to_string(index) + ": " + e.what());
        }
        check_mesh(mesh);  // e.g. a transform that overflows the float range
        mesh.material = material;
        meshes.push_back(std::move(mesh));
      }
    }
    return meshes;
  } catch (const Error& e) {
    throw Error(file.string() + ": " + e.what());
  } catch (const std::exception& e) {  // tinygltf or the allocator; keep the one-line contract
    throw Error(file.string() + ": cannot load glTF: " + one_line(e.what()));
  }
}

}  // namespace facet
