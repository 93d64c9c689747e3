// The in-memory scene: what a scene file describes, after validation, in world space.
//
// Loaded by load_scene() (scene_loader.hpp) from the JSON format documented in
// scenes/README.md. Everything here is plain data in double precision; the GPU passes
// flatten it into the float layouts of shaders/lib/scene_layout.glsl.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

namespace facet {

struct Camera {
  glm::dvec3 position{0.0, 1.0, 5.0};
  glm::dvec3 target{0.0, 0.0, 0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fov_y_deg = 45.0;  // full vertical field of view
  int width = 640;
  int height = 360;
};

struct DirectionalLight {
  glm::dvec3 direction{0.0, 1.0, 0.0};  // unit vector from the surface toward the light
  glm::dvec3 irradiance{1.0, 1.0, 1.0};  // RGB irradiance on a surface facing the light
};

struct LambertMaterial {
  glm::dvec3 albedo{0.8, 0.8, 0.8};
};

// Ids of the normal distributions of shaders/lib/cross_section.glsl.
enum class Ndf : int { Beckmann = 0, Ggx = 1, Ellipsoidal = 2, SphericalGaussian = 3 };

// A semi-infinite half-space of specular microflakes with normal distribution `ndf`
// (docs/microflake_brdf.md): from a mirror (small alpha) to an isotropic medium (large alpha,
// or b -> 0). `albedo` scales the single-scattering BRDF per colour channel.
struct MicroflakeMaterial {
  Ndf ndf = Ndf::SphericalGaussian;
  double param = 0.5;  // alpha (beckmann, ggx, sg) or b (kk)
  glm::dvec3 albedo{1.0, 1.0, 1.0};
};

// One alternative per material kind; later issues add theirs here.
using Material = std::variant<LambertMaterial, MicroflakeMaterial>;

// An infinite plane through `point` with unit normal `normal`.
struct Plane {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 1.0, 0.0};
  uint32_t material = 0;
};

struct Sphere {
  glm::dvec3 center{0.0};
  double radius = 1.0;
  uint32_t material = 0;
};

// A triangle mesh in world space (the scene's transform already applied).
struct Mesh {
  std::string name;
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // per vertex, unit; empty means flat shading
  std::vector<glm::dvec2> uvs;      // per vertex; may be empty
  // Per vertex, optional (only with normals): xyz = unit tangent along +u, w = +-1 handedness,
  // bitangent = w * cross(normal, tangent.xyz) as in glTF 2.0.
  std::vector<glm::dvec4> tangents;
  std::vector<uint32_t> indices;    // three per triangle
  uint32_t material = 0;

  size_t triangle_count() const { return indices.size() / 3; }
};

struct Scene {
  std::filesystem::path source;  // the scene file, for metadata and relative paths
  Camera camera;
  DirectionalLight light;
  glm::dvec3 ambient{0.0};     // constant RGB irradiance added to every lit point
  glm::dvec3 background{0.0};  // RGB radiance of rays that hit nothing
  std::vector<Material> materials;
  std::vector<std::string> material_names;  // parallel to materials, for messages and metadata
  std::vector<Plane> planes;
  std::vector<Sphere> spheres;
  std::vector<Mesh> meshes;
};

}  // namespace facet
