#include "scene/scene_loader.hpp"

#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <vector>

#include "common/error.hpp"
#include "common/json_object_reader.hpp"
#include "common/json_overrides.hpp"
#include "scene/camera_path.hpp"
#include "scene/diffraction_material_reader.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/plane_frame.hpp"
#include "scene/subpixel_materials.hpp"
#include "scene/transform.hpp"

namespace facet {

namespace {

using Json = nlohmann::json;
using MaterialIndex = std::map<std::string, uint32_t>;

std::string display_name(const std::filesystem::path& source) {
  return source.empty() ? std::string("<scene>") : source.string();
}

Camera read_camera(JsonObjectReader r) {
  Camera c;
  c.position = r.vec3("position", c.position);
  c.target = r.vec3("target", c.target);
  c.up = r.nonzero_vec3("up", c.up);
  c.fov_y_deg = r.number("fov_y", c.fov_y_deg);
  if (!(c.fov_y_deg > 0.0 && c.fov_y_deg < 180.0)) r.fail("fov_y", "must be in (0, 180) degrees");
  c.width = r.integer_in("width", 1, kMaxImageSide, c.width);
  c.height = r.integer_in("height", 1, kMaxImageSide, c.height);
  r.finish();
  if (const char* defect = camera_defect(c))
    r.fail(defect, defect == std::string("target") ? "must differ from camera.position"
                                                   : "must not be parallel to the view direction");
  return c;
}

DirectionalLight read_light(JsonObjectReader r) {
  DirectionalLight l;
  l.direction = glm::normalize(r.nonzero_vec3("direction", l.direction));
  l.irradiance = r.colour("irradiance", l.irradiance);
  r.finish();
  return l;
}

Material read_material(JsonObjectReader r, const std::filesystem::path& base_dir) {
  const std::string type = r.string("type");
  if (type == "lambert") {
    LambertMaterial m;
    m.albedo = r.colour("albedo", m.albedo, 1.0);
    r.finish();
    return m;
  }
  if (type == "microflake") {
    MicroflakeMaterial m;
    const std::string ndf = r.string("ndf");
    const char* names[] = {"beckmann", "ggx", "kk", "sg"};
    int id = -1;
    for (int i = 0; i < 4; ++i)
      if (ndf == names[i]) id = i;
    if (id < 0) r.fail("ndf", "must be one of: beckmann, ggx, kk, sg");
    m.ndf = static_cast<Ndf>(id);
    m.param = r.number("param");
    // The validated domain of the cross-section kernels (docs/cross_sections.md).
    if (m.ndf == Ndf::Ellipsoidal ? !(m.param > 0.0 && m.param < 1.0) : !(m.param >= 1e-3 && m.param <= 1e3))
      r.fail("param", m.ndf == Ndf::Ellipsoidal ? "(b) must lie in (0, 1)" : "(alpha) must lie in [1e-3, 1e3]");
    m.albedo = r.colour("albedo", m.albedo, 1.0);
    r.finish();
    return m;
  }
  if (type == "colormap_texture") return read_colormap_texture_material(r, base_dir);
  if (type == "microsurface") return read_microsurface_material(r, base_dir);
  if (type == "diffraction") return read_diffraction_material(r, base_dir);
  r.fail("type", "must be one of: lambert, microflake, colormap_texture, microsurface, diffraction");
}

uint32_t read_material_ref(JsonObjectReader& r, const MaterialIndex& materials) {
  const std::string name = r.string("material");
  const auto it = materials.find(name);
  if (it == materials.end()) {
    std::string known;
    for (const auto& [k, v] : materials) known += (known.empty() ? "" : ", ") + k;
    r.fail("material",
           "must name a material in \"materials\" (defined: " + (known.empty() ? std::string("none") : known) + ")");
  }
  return it->second;
}

glm::dmat4 read_transform(JsonObjectReader r) {
  const glm::dvec3 translate = r.vec3("translate", glm::dvec3(0.0));
  const glm::dvec3 rotate_deg = r.vec3("rotate_deg", glm::dvec3(0.0));
  glm::dvec3 scale(1.0);
  if (r.has("scale")) {
    const Json& s = r.value("scale");
    if (s.is_array()) {
      scale = r.vec3("scale");
      if (scale.x == 0.0 || scale.y == 0.0 || scale.z == 0.0) {
        r.fail("scale", "must have non-zero components");
      }
    } else {
      scale = glm::dvec3(r.positive_number("scale"));
    }
  }
  r.finish();
  return translate_rotate_scale(translate, rotate_deg, scale);
}

Plane read_plane(JsonObjectReader& r, const MaterialIndex& materials, const Scene& scene) {
  Plane p;
  p.point = r.vec3("point");
  p.normal = glm::normalize(r.nonzero_vec3("normal"));
  if (r.has("tangent")) {
    p.tangent = glm::normalize(r.nonzero_vec3("tangent"));
    // sin of the angle to the normal; 1e-6 rad leaves a usable frame.
    if (!(glm::length(glm::cross(p.tangent, p.normal)) > 1e-6)) r.fail("tangent", "must not be parallel to the normal");
  }
  p.tangent = plane_frame(p).tangent;  // the derived default, or the given one made perpendicular
  p.uv_scale = r.vec2("uv_scale", p.uv_scale);
  if (!(p.uv_scale.x != 0.0 && p.uv_scale.y != 0.0)) r.fail("uv_scale", "must have non-zero components");
  if (r.has("size")) {
    p.size = r.vec2("size");
    if (!(p.size->x > 0.0 && p.size->y > 0.0)) r.fail("size", "must be [w, h] with w, h > 0");
  }
  p.material = read_material_ref(r, materials);
  if (std::holds_alternative<MicrosurfaceMaterial>(scene.materials[p.material]) && !p.size)
    r.fail("material", "is a microsurface, which needs a finite plane (give the plane a \"size\")");
  return p;
}

void read_object(JsonObjectReader r, const MaterialIndex& materials, const std::filesystem::path& base_dir,
                 const std::string& path, Scene& scene) {
  const std::string type = r.string("type");
  const auto reject_microsurface = [&](uint32_t material) {
    if (std::holds_alternative<MicrosurfaceMaterial>(scene.materials[material]))
      r.fail("material", "is a microsurface, which only finite planes can have");
  };
  if (type == "plane") {
    const Plane p = read_plane(r, materials, scene);
    r.finish();
    scene.planes.push_back(p);
  } else if (type == "sphere") {
    Sphere s;
    s.center = r.vec3("center");
    s.radius = r.positive_number("radius");
    s.material = read_material_ref(r, materials);
    reject_microsurface(s.material);
    r.finish();
    scene.spheres.push_back(s);
  } else if (type == "mesh") {
    const std::string file = r.string("file");
    if (file.empty()) r.fail("file", "must be a non-empty path");
    const uint32_t material = read_material_ref(r, materials);
    reject_microsurface(material);
    const glm::dmat4 transform =
        r.has("transform") ? read_transform(JsonObjectReader(r.value("transform"), r.file(), r.key_path("transform")))
                           : glm::dmat4(1.0);
    r.finish();
    std::vector<Mesh> meshes;
    try {
      meshes = load_gltf_meshes(base_dir / file, transform, material);
    } catch (const Error& e) {
      throw Error(r.file() + ": " + path + ".file: " + e.what());
    }
    for (Mesh& m : meshes) scene.meshes.push_back(std::move(m));
  } else {
    r.fail("type", "must be one of: plane, sphere, mesh");
  }
}

// Rejects duplicate keys and deep nesting while parsing: nlohmann keeps the last duplicate
// silently, and deep nesting would make later recursive walks (dump) overflow the stack.
class StrictParseCallback {
 public:
  bool operator()(int depth, Json::parse_event_t event, Json& parsed) {
    if (depth > kMaxJsonDepth) {
      throw Error("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    if (event == Json::parse_event_t::object_start) keys_.emplace_back();
    if (event == Json::parse_event_t::object_end) keys_.pop_back();
    if (event == Json::parse_event_t::key && !keys_.back().insert(parsed.get<std::string>()).second) {
      throw Error("duplicate key \"" + parsed.get<std::string>() + "\"");
    }
    return true;
  }

 private:
  std::vector<std::set<std::string>> keys_;
};

std::pair<size_t, size_t> line_and_column(const std::string& text, size_t byte) {
  size_t line = 1, column = 1;
  for (size_t i = 0; i + 1 < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

}  // namespace

const char* material_type_name(const Material& material) {
  constexpr const char* names[] = {"lambert", "microflake", "colormap_texture", "microsurface", "diffraction"};
  static_assert(std::variant_size_v<Material> == std::size(names));
  return names[material.index()];
}

Scene parse_scene(const Json& document, const std::filesystem::path& source) {
  const std::string file = display_name(source);
  JsonObjectReader top(document, file, "");
  Scene scene;
  scene.source = source;

  if (top.has("camera")) scene.camera = read_camera(JsonObjectReader(top.value("camera"), file, "camera"));
  if (top.has("camera_path"))
    scene.camera_path = read_camera_path(JsonObjectReader(top.value("camera_path"), file, "camera_path"), scene.camera);
  if (top.has("light")) scene.light = read_light(JsonObjectReader(top.value("light"), file, "light"));
  scene.ambient = top.colour("ambient", scene.ambient);
  scene.background = top.colour("background", scene.background);

  MaterialIndex material_index;
  if (top.has("materials")) {
    const Json& materials = top.value("materials");
    if (!materials.is_object()) top.fail("materials", "must be an object mapping names to materials");
    for (const auto& [name, m] : materials.items()) {
      material_index[name] = static_cast<uint32_t>(scene.materials.size());
      scene.materials.push_back(read_material(JsonObjectReader(m, file, "materials." + name), source.parent_path()));
      scene.material_names.push_back(name);
    }
  }

  if (top.has("objects")) {
    const Json& objects = top.value("objects");
    if (!objects.is_array()) top.fail("objects", "must be an array");
    const std::filesystem::path base_dir = source.parent_path();
    for (size_t i = 0; i < objects.size(); ++i) {
      const std::string path = "objects[" + std::to_string(i) + "]";
      read_object(JsonObjectReader(objects[i], file, path), material_index, base_dir, path, scene);
    }
  }
  top.finish();
  return scene;
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  const std::string extension = file.extension().string();
  if (extension == ".gltf" || extension == ".glb") return load_gltf_scene(file, overrides);
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec)) {
    throw Error(display_name(file) + ": cannot open for reading");
  }
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Json document;
  try {
    document = Json::parse(text, StrictParseCallback());
  } catch (const Json::parse_error& e) {
    const auto [line, column] = line_and_column(text, e.byte);
    // nlohmann's message is "[json.exception...] parse error at line L, column C: <reason>".
    std::string reason = e.what();
    const size_t colon = reason.find(": ", reason.find("column"));
    if (colon != std::string::npos) reason = reason.substr(colon + 2);
    for (char& ch : reason) {
      if (ch == '\n' || ch == '\r') ch = ' ';  // the message stays one line
    }
    throw Error(display_name(file) + ": invalid JSON at line " + std::to_string(line) + ", column " +
                std::to_string(column) + ": " + reason);
  } catch (const Json::exception& e) {  // e.g. out_of_range.406 for a number like 1e400
    std::string reason = e.what();
    const size_t bracket = reason.find("] ");
    if (bracket != std::string::npos) reason = reason.substr(bracket + 2);
    throw Error(display_name(file) + ": invalid JSON: " + reason);
  } catch (const Error& e) {
    throw Error(display_name(file) + ": invalid JSON: " + e.what());
  }
  for (const std::string& assignment : overrides) apply_override(document, assignment, display_name(file));
  Scene scene = parse_scene(document, file);
  scene.overrides = overrides;
  return scene;
}

}  // namespace facet
