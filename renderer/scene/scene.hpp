// The in-memory scene: what a scene file describes, after validation, in world space.
//
// Loaded by load_scene() (scene_loader.hpp) from the JSON format documented in
// scenes/README.md. Everything here is plain data in double precision; the GPU passes
// flatten it into the float layouts of shaders/lib/scene_layout.glsl.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "assets/scalar_field.hpp"
#include "scene/colormap.hpp"
#include "scene/grating/diffraction_method.hpp"
#include "scene/grating/grating.hpp"
#include "scene/grating/illuminant.hpp"

namespace facet {

struct Camera {
  glm::dvec3 position{0.0, 1.0, 5.0};
  glm::dvec3 target{0.0, 0.0, 0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  double fov_y_deg = 45.0;  // full vertical field of view
  int width = 640;
  int height = 360;
};

// One keyframe of a camera path: the pose the camera takes at `frame`.
struct CameraKey {
  int frame = 0;
  glm::dvec3 position{0.0};
  glm::dvec3 target{0.0};
  double fov_y_deg = 45.0;
};

// An animation of the camera (scene/camera_path.hpp): `frames` frames numbered 0..frames-1, poses
// interpolated between keys sorted by frame (up, width and height stay those of Scene::camera).
struct CameraPath {
  enum class Interpolation { Linear, Smooth };
  int frames = 1;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<CameraKey> keys;
};

struct DirectionalLight {
  glm::dvec3 direction{0.0, 1.0, 0.0};   // unit vector from the surface toward the light
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

// A periodic scalar texture (values wrap at its borders), shared with whatever renders it.
using ScalarTexture = std::shared_ptr<const assets::ScalarField>;

// Lambertian, with albedo = colormap(texture(uv)): a scalar texture seen through a colour map
// (docs/reference.md). The texture repeats with period 1 in uv; texel (i, j) has its centre at
// uv = ((i + 1/2)/W, (j + 1/2)/H) and values between centres are bilinear.
struct ColormapTextureMaterial {
  ScalarTexture texture;
  Colormap colormap;
};

// Specular Beckmann microfacets below the resolution of a height field, on the local normal of the
// field: f = reflectance · D(h) G2(i, o) / (4 cos_i cos_o) in the frame of that normal.
struct BeckmannSpecular {
  glm::dvec2 alpha{0.1, 0.1};  // roughness along the plane's tangent and bitangent
  glm::dvec3 reflectance{0.04, 0.04, 0.04};
};

// A height field at micro scale laid on a finite plane (tiling across it), rendered as real
// geometry by the reference. Lambertian with albedo = height_colormap(z) · slope_colormap(|∇z|)
// (each factor only when given), plus the optional specular lobe.
struct MicrosurfaceMaterial {
  ScalarTexture heights;                    // h, as loaded or generated
  double texel_size = 1.0;                  // Δ, world units
  double height_scale = 1.0;                // world height z = height_scale · h
  std::optional<Colormap> height_colormap;  // of z, world units
  std::optional<Colormap> slope_colormap;   // of |∇z| = tan of the local tilt
  std::optional<BeckmannSpecular> specular;
};

// A diffraction grating tiled over the surface (Stam's BRDF, docs/diffraction.md), integrated over
// wavelength against the CIE observer and `illuminant`, over a Lambertian base. The grating's y axis
// (its ridges) follows the surface tangent dp/du, its height the normal. Counts of 0 are chosen from
// `tolerance`; the spectral tables are built by the renderer (diffraction/prepared_diffraction.hpp).
struct DiffractionMaterial {
  std::shared_ptr<const diffraction::Grating> grating;
  double tolerance = 1e-3;
  diffraction::Illuminant illuminant = diffraction::Illuminant::D65;
  int wavelengths = 0;  // wavelength samples over 360..830 nm
  int taylor = 0;       // Taylor terms
  glm::dvec3 base_albedo{0.0};
  diffraction::DiffractionMethod method = diffraction::DiffractionMethod::Spectral;  // `--diffraction` overrides
};

// One alternative per material kind; later issues add theirs here.
using Material = std::variant<LambertMaterial, MicroflakeMaterial, ColormapTextureMaterial, MicrosurfaceMaterial,
                              DiffractionMaterial>;

// "lambert", "microflake", "colormap_texture", "microsurface", "diffraction": for messages.
const char* material_type_name(const Material& material);

// A plane through `point` with unit normal `normal`; infinite unless `size` is given.
// Its frame is (tangent, bitangent = normal × tangent, normal) (plane_frame.hpp); surface
// coordinates (x, y) along tangent and bitangent are measured from `point`, and uv = (x, y) · uv_scale.
struct Plane {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0.0, 1.0, 0.0};
  uint32_t material = 0;
  glm::dvec3 tangent{0.0};  // unit, perpendicular to normal; zero: derived from the normal
  glm::dvec2 uv_scale{1.0, 1.0};
  std::optional<glm::dvec2> size{};  // [w, h]: the rectangle |x| <= w/2, |y| <= h/2
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
  std::vector<uint32_t> indices;  // three per triangle
  uint32_t material = 0;

  size_t triangle_count() const { return indices.size() / 3; }
};

struct Scene {
  std::filesystem::path source;  // the scene file, for metadata and relative paths
  std::vector<std::string> overrides;  // the --set PATH=VALUE applied to it, as given (facet:set)
  Camera camera;
  std::optional<CameraPath> camera_path;  // frames of an animation; absent: one frame, `camera`
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
