#include "scene/gltf_scene.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <set>

#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "common/json_object_reader.hpp"
#include "common/json_overrides.hpp"
#include "scene/camera_path.hpp"
#include "scene/gltf_animation.hpp"
#include "scene/gltf_model.hpp"
#include "scene/scene_loader.hpp"

namespace facet {

namespace {

using Json = nlohmann::json;

constexpr const char* kLightsExtension = "KHR_lights_punctual";
// |cos| between an animated camera's x axis and the world's +y above which the camera counts as
// rolled (0.006°: float data of an unrolled camera stays far below).
constexpr double kRollTolerance = 1e-4;

Json json_vec3(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }

// A glTF extras block (tinygltf keeps its JSON text) as JSON; null when absent.
Json parse_extras(const std::string& text, const std::string& what) {
  if (text.empty()) return nullptr;
  try {
    return Json::parse(text);
  } catch (const Json::exception&) {
    throw Error(what + ": extras are not valid JSON");
  }
}

// The world transforms of the default scene's nodes (absent for nodes outside it), their parents,
// and the order load_gltf_meshes() visits them in (so both give the same meshes in the same order).
struct Hierarchy {
  std::vector<std::optional<glm::dmat4>> world;
  std::vector<int> parent;  // -1 for roots
  std::vector<size_t> order;
};

Hierarchy read_hierarchy(const tinygltf::Model& model) {
  Hierarchy h{std::vector<std::optional<glm::dmat4>>(model.nodes.size()), std::vector<int>(model.nodes.size(), -1), {}};
  for (size_t i = 0; i < model.nodes.size(); ++i)
    for (int c : model.nodes[i].children)
      if (c >= 0 && static_cast<size_t>(c) < model.nodes.size()) h.parent[static_cast<size_t>(c)] = static_cast<int>(i);
  for_each_gltf_node(model, glm::dmat4(1.0), [&](size_t node, const glm::dmat4& world) {
    h.world[node] = world;
    h.order.push_back(node);
  });
  return h;
}

// A camera node's placement: glTF cameras look down their local -z with +y up (glTF 2.0 §3.10.1).
struct CameraPose {
  glm::dvec3 position, forward, up, right;  // directions unit
};

CameraPose camera_pose(const glm::dmat4& world, size_t node) {
  const glm::dvec3 axes[3] = {glm::dvec3(world[0]), glm::dvec3(world[1]), -glm::dvec3(world[2])};
  for (const glm::dvec3& a : axes)
    if (!(glm::length(a) > 0.0) || !std::isfinite(glm::length(a)) || !std::isfinite(glm::length(glm::dvec3(world[3]))))
      throw Error("camera node " + std::to_string(node) + ": its world transform is singular or not finite");
  return {glm::dvec3(world[3]), glm::normalize(axes[2]), glm::normalize(axes[1]), glm::normalize(axes[0])};
}

// The perspective camera of the node with the lowest index in the default scene.
size_t camera_node(const tinygltf::Model& model, const Hierarchy& h) {
  bool orthographic = false;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const int c = model.nodes[i].camera;
    if (!h.world[i] || c < 0) continue;
    if (static_cast<size_t>(c) >= model.cameras.size())
      throw Error("node " + std::to_string(i) + " references missing camera " + std::to_string(c));
    if (model.cameras[static_cast<size_t>(c)].type == "perspective") return i;
    orthographic = true;
  }
  throw Error(orthographic ? "has only orthographic cameras; facet renders a perspective camera"
                           : "has no camera in its scene; facet renders a scene through its perspective camera");
}

// The node's camera as facet's "camera" (up: the camera's own, or the given one) and its path.
void add_camera(const tinygltf::Model& model, const Hierarchy& h, double fps, Json& doc) {
  const size_t node = camera_node(model, h);
  const std::string where = "camera node " + std::to_string(node);
  const tinygltf::PerspectiveCamera& lens = model.cameras[static_cast<size_t>(model.nodes[node].camera)].perspective;
  const double fov_y = glm::degrees(lens.yfov);
  if (!(fov_y > 0.0 && fov_y < 180.0)) throw Error(where + ": yfov must lie in (0, pi) radians");
  Json camera = {{"fov_y", fov_y}};
  if (lens.aspectRatio > 0.0) {
    const double width = std::round(kDefaultGltfHeight * lens.aspectRatio);
    if (!(width >= 1.0 && width <= kMaxImageSide))
      throw Error(where + ": aspectRatio " + std::to_string(lens.aspectRatio) + " gives a width outside [1, " +
                  std::to_string(kMaxImageSide) + "] at the height " + std::to_string(kDefaultGltfHeight));
    camera["width"] = static_cast<int>(width);
    camera["height"] = kDefaultGltfHeight;
  }

  const std::optional<GltfNodeAnimation> animation = read_gltf_node_animation(model, node);
  const glm::dmat4 parent_world = h.parent[node] >= 0 ? *h.world[static_cast<size_t>(h.parent[node])] : glm::dmat4(1.0);
  const auto place = [&](const CameraPose& pose, const glm::dvec3& up) {
    camera["position"] = json_vec3(pose.position);
    camera["target"] = json_vec3(pose.position + pose.forward);
    camera["up"] = json_vec3(up);
  };
  const double span = animation ? std::round((animation->end - animation->start) * fps) : 0.0;
  if (!(span < kMaxGltfPathFrames))
    throw Error(where + ": its animation lasts more than " + std::to_string(kMaxGltfPathFrames) + " frames at " +
                std::to_string(fps) + " fps");
  const int frames = static_cast<int>(span) + 1;
  if (frames == 1) {
    const CameraPose pose = camera_pose(
        animation ? parent_world * animated_local_transform(model.nodes[node], node, *animation, animation->start)
                  : *h.world[node],
        node);
    place(pose, pose.up);
    doc["camera"] = camera;
    return;
  }
  // Only the camera node's own animation is sampled: a moving parent would be ignored, so refuse it.
  for (size_t a = 0; a < model.animations.size(); ++a)
    for (const tinygltf::AnimationChannel& channel : model.animations[a].channels)
      for (int n = h.parent[node]; n >= 0; n = h.parent[static_cast<size_t>(n)])
        if (channel.target_node == n && channel.target_path != "weights")
          throw Error("animation " + std::to_string(a) + " moves node " + std::to_string(n) + ", a parent of " + where +
                      "; only the camera node's own animation is imported");
  // A camera path keeps one up vector, the world's +y: each frame must be upright without roll.
  const glm::dvec3 world_up(0.0, 1.0, 0.0);
  Json keys = Json::array();
  for (int f = 0; f < frames; ++f) {
    const double t = animation->start + f / fps;
    const CameraPose pose =
        camera_pose(parent_world * animated_local_transform(model.nodes[node], node, *animation, t), node);
    if (std::abs(glm::dot(pose.right, world_up)) > kRollTolerance || !(glm::dot(pose.up, world_up) > 0.0))
      throw Error(where + ": rolls or turns upside down at frame " + std::to_string(f) +
                  " of its animation (a camera path keeps +y up)");
    if (f == 0) place(pose, world_up);
    keys.push_back({{"frame", f},
                    {"position", json_vec3(pose.position)},
                    {"target", json_vec3(pose.position + pose.forward)},
                    {"fov_y", fov_y}});
  }
  doc["camera"] = camera;
  doc["camera_path"] = {{"frames", frames}, {"interpolation", "linear"}, {"keys", keys}};
}

// The one directional light among the scene's nodes, as facet's "light"; without one, facet's default
// light, written out so that `--set light.irradiance=...` has a key to change.
void add_light(const tinygltf::Model& model, const Hierarchy& h, Json& doc) {
  const DirectionalLight default_light;
  doc["light"] = {{"direction", json_vec3(default_light.direction)},
                  {"irradiance", json_vec3(default_light.irradiance)}};
  std::optional<size_t> lit_by;
  for (size_t i = 0; i < model.nodes.size(); ++i) {
    const auto ext = model.nodes[i].extensions.find(kLightsExtension);
    if (!h.world[i] || ext == model.nodes[i].extensions.end()) continue;
    const std::string where = "node " + std::to_string(i);
    const tinygltf::Value& v = ext->second;
    if (!v.IsObject() || !v.Has("light") || !v.Get("light").IsInt())
      throw Error(where + ": " + kLightsExtension + " needs an integer \"light\"");
    const int index = v.Get("light").GetNumberAsInt();
    if (index < 0 || static_cast<size_t>(index) >= model.lights.size())
      throw Error(where + " references missing light " + std::to_string(index));
    const tinygltf::Light& light = model.lights[static_cast<size_t>(index)];
    if (light.type != "directional")
      throw Error(where + " carries light " + std::to_string(index) + ", a " + light.type +
                  " light; facet renders one directional light");
    if (lit_by)
      throw Error("nodes " + std::to_string(*lit_by) + " and " + std::to_string(i) +
                  " both carry a directional light; facet renders one");
    lit_by = i;
    // KHR_lights_punctual: light travels along the node's local -z; facet's direction points to the light.
    const glm::dvec3 toward = glm::dvec3((*h.world[i])[2]);
    if (!(glm::length(toward) > 0.0) || !std::isfinite(glm::length(toward)))
      throw Error(where + ": its world transform is singular or not finite");
    if (!light.color.empty() && light.color.size() != 3)
      throw Error("light " + std::to_string(index) + ": color needs 3 numbers");
    const glm::dvec3 colour =
        light.color.empty() ? glm::dvec3(1.0) : glm::dvec3(light.color[0], light.color[1], light.color[2]);
    doc["light"] = {{"direction", json_vec3(glm::normalize(toward))},
                    {"irradiance", json_vec3(colour * light.intensity)}};
  }
}

// A JSON key per glTF material (its name, made unique), then "default" for primitives without one.
std::vector<std::string> material_keys(const tinygltf::Model& model) {
  std::vector<std::string> keys;
  std::set<std::string> taken;
  for (size_t i = 0; i <= model.materials.size(); ++i) {
    const std::string name = i == model.materials.size() ? "default" : model.materials[i].name;
    std::string key = name.empty() ? "material " + std::to_string(i) : name;
    while (taken.count(key)) key += " (" + std::to_string(i) + ")";
    taken.insert(key);
    keys.push_back(key);
  }
  return keys;
}

// Each glTF material's extras.facet as it is, else Lambert with the base colour (glTF's default
// material, white, for primitives without one).
void add_materials(const tinygltf::Model& model, const std::vector<std::string>& keys, Json& doc) {
  doc["materials"] = Json::object();
  for (size_t i = 0; i < model.materials.size(); ++i) {
    const tinygltf::Material& m = model.materials[i];
    const Json e = parse_extras(m.extras_json_string, "material " + std::to_string(i));
    if (e.is_object() && e.contains("facet")) {
      doc["materials"][keys[i]] = e["facet"];
    } else {
      const std::vector<double>& c = m.pbrMetallicRoughness.baseColorFactor;
      if (c.size() != 4) throw Error("material " + std::to_string(i) + ": baseColorFactor needs 4 numbers");
      doc["materials"][keys[i]] = {{"type", "lambert"}, {"albedo", {c[0], c[1], c[2]}}};
    }
  }
  bool needs_default = false;
  for (const tinygltf::Mesh& mesh : model.meshes)
    for (const tinygltf::Primitive& p : mesh.primitives) needs_default |= p.material < 0;
  if (needs_default) doc["materials"][keys.back()] = {{"type", "lambert"}, {"albedo", {1.0, 1.0, 1.0}}};
}

// The root's extras.facet: the frame rate of camera paths, ambient and background (facet's defaults,
// written out for `--set`, when not given).
double add_root_settings(const tinygltf::Model& model, const std::string& file, Json& doc) {
  const Scene defaults;
  doc["ambient"] = json_vec3(defaults.ambient);
  doc["background"] = json_vec3(defaults.background);
  const Json e = parse_extras(model.extras_json_string, file);
  if (!e.is_object() || !e.contains("facet")) return kDefaultGltfFps;
  JsonObjectReader r(e["facet"], file, "extras.facet");
  const double fps = r.positive_number("fps", kDefaultGltfFps);
  for (const char* key : {"ambient", "background"})
    if (r.has(key)) doc[key] = r.value(key);
  r.finish();
  return fps;
}

}  // namespace

Scene load_gltf_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  tinygltf::Model model;
  Hierarchy hierarchy;
  std::vector<std::string> keys;
  Json doc = Json::object();
  try {
    model = load_gltf_model(file, {kLightsExtension});
    hierarchy = read_hierarchy(model);
  } catch (const std::exception&) {
    rethrow_as_gltf_error(file);
  }
  const double fps = add_root_settings(model, file.string(), doc);  // its messages name the file
  try {
    add_camera(model, hierarchy, fps, doc);
    add_light(model, hierarchy, doc);
    keys = material_keys(model);
    add_materials(model, keys, doc);
  } catch (const std::exception&) {
    rethrow_as_gltf_error(file);
  }
  for (const std::string& assignment : overrides) apply_override(doc, assignment, file.string());
  Scene scene = parse_scene(doc, file);
  scene.overrides = overrides;

  // parse_scene numbers the materials in its own order: map the glTF indices by key.
  std::map<std::string, uint32_t> index_of;
  for (size_t i = 0; i < scene.material_names.size(); ++i) index_of[scene.material_names[i]] = static_cast<uint32_t>(i);
  const auto material_of = [&](int gltf_material) {
    if (gltf_material >= 0 && static_cast<size_t>(gltf_material) >= model.materials.size())
      throw Error("a primitive references missing material " + std::to_string(gltf_material));
    const std::string& key = gltf_material >= 0 ? keys[static_cast<size_t>(gltf_material)] : keys.back();
    const auto found = index_of.find(key);
    if (found == index_of.end()) throw Error("material \"" + key + "\" was removed by --set");
    const uint32_t index = found->second;
    if (std::holds_alternative<MicrosurfaceMaterial>(scene.materials[index]))
      throw Error("material \"" + key + "\" is a microsurface, which only finite planes can have");
    return index;
  };
  try {
    for (size_t node : hierarchy.order)
      for (Mesh& m : read_gltf_node_meshes(model, node, *hierarchy.world[node], material_of))
        scene.meshes.push_back(std::move(m));
  } catch (const std::exception&) {
    rethrow_as_gltf_error(file);
  }
  return scene;
}

}  // namespace facet
