#include "gpu/scene_upload.hpp"

#include <cmath>
#include <cstring>
#include <span>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "common/error.hpp"
#include "gpu/microsurface_upload.hpp"
#include "gpu/render_layout.hpp"
#include "gpu/texture_upload.hpp"
#include "scene/bvh.hpp"
#include "scene/camera_frame.hpp"
#include "scene/plane_frame.hpp"

namespace facet::gpu {

namespace {

vec4 to_vec4(glm::dvec3 v, double w = 0.0) { return vec4(glm::vec3(v), static_cast<float>(w)); }

std::vector<GpuTriangle> flatten_triangles(const Scene& scene, const Bvh& bvh) {
  std::vector<GpuTriangle> triangles;
  triangles.reserve(bvh.triangles.size());
  for (const BvhTriangleRef& ref : bvh.triangles) {
    const Mesh& mesh = scene.meshes[ref.mesh];
    GpuTriangle tri{};
    vec4* positions[3] = {&tri.p0, &tri.p1, &tri.p2};
    vec4* normals[3] = {&tri.n0, &tri.n1, &tri.n2};
    // Without uvs, a triangle's uv are its barycentrics, as RayCaster reports them.
    glm::vec2 uvs[3] = {{0, 0}, {1, 0}, {0, 1}};
    for (int corner = 0; corner < 3; ++corner) {
      uint32_t vertex = mesh.indices[3 * ref.triangle + corner];
      *positions[corner] = to_vec4(mesh.positions[vertex]);
      if (!mesh.normals.empty()) *normals[corner] = to_vec4(mesh.normals[vertex]);
      if (!mesh.uvs.empty()) uvs[corner] = glm::vec2(mesh.uvs[vertex]);
    }
    tri.uv01 = vec4(uvs[0], uvs[1]);
    tri.uv2 = vec4(uvs[2], 0, 0);
    tri.material = uvec4(mesh.material);
    triangles.push_back(tri);
  }
  return triangles;
}

}  // namespace

std::vector<const vk::Buffer*> SceneBuffers::bindings(const vk::Buffer& pixels) const {
  std::vector<const vk::Buffer*> slots(FACET_RENDER_SCENE_BINDING_COUNT);
  slots[FACET_RENDER_BINDING_GLOBALS] = &globals;
  slots[FACET_RENDER_BINDING_PLANES] = &planes;
  slots[FACET_RENDER_BINDING_SPHERES] = &spheres;
  slots[FACET_RENDER_BINDING_BVH_NODES] = &nodes;
  slots[FACET_RENDER_BINDING_TRIANGLES] = &triangles;
  slots[FACET_RENDER_BINDING_MATERIALS] = &materials;
  slots[FACET_RENDER_BINDING_PIXELS] = &pixels;
  slots[FACET_RENDER_BINDING_TEXTURE_LEVELS] = &texture_levels;
  slots[FACET_RENDER_BINDING_TEXELS] = &texels;
  slots[FACET_RENDER_BINDING_COLORMAPS] = &colormaps;
  slots[FACET_RENDER_BINDING_COLORMAP_POINTS] = &colormap_points;
  return slots;
}

std::vector<vk::BufferKind> SceneBuffers::binding_kinds() {
  std::vector<vk::BufferKind> kinds(FACET_RENDER_SCENE_BINDING_COUNT, vk::BufferKind::Texels);
  kinds[FACET_RENDER_BINDING_GLOBALS] = vk::BufferKind::Uniform;
  kinds[FACET_RENDER_BINDING_PIXELS] = vk::BufferKind::Storage;
  return kinds;
}

void SceneBuffers::set_camera(const Scene& scene, const Camera& camera, int width, int height) {
  const CameraFrame frame = camera_frame(camera, width, height);
  GpuGlobals g{};
  g.camera_origin = to_vec4(frame.origin);
  g.camera_forward = to_vec4(frame.forward);
  g.camera_right = to_vec4(frame.right);
  g.camera_up = to_vec4(frame.up);
  g.light_direction = to_vec4(scene.light.direction);
  g.light_irradiance = to_vec4(scene.light.irradiance);
  g.ambient = to_vec4(scene.ambient);
  g.background = to_vec4(scene.background);
  g.image = uvec4(width, height, 0, 0);
  g.counts = counts;
  globals.upload(&g, sizeof(g));
}

SceneBuffers upload_scene(vk::Context& context, const Scene& scene, bool colormap_tables) {
  std::vector<GpuPlane> planes;
  for (const Plane& p : scene.planes) {
    const PlaneFrame frame = plane_frame(p);
    const glm::dvec2 half_size = p.size ? 0.5 * *p.size : glm::dvec2(0.0);
    planes.push_back({to_vec4(p.point), to_vec4(frame.normal), to_vec4(frame.tangent),
                      vec4(glm::vec2(p.uv_scale), glm::vec2(half_size)), uvec4(p.material)});
  }
  std::vector<GpuSphere> spheres;
  for (const Sphere& s : scene.spheres) spheres.push_back({to_vec4(s.center, s.radius), uvec4(s.material)});
  TextureData textures;
  std::vector<GpuMaterial> materials;
  const auto add_materials = [&] {
    uint32_t diffraction_index = 0;  // the order of upload_diffraction (gpu/diffraction_upload.hpp)
    for (const Material& material : scene.materials)
      materials.push_back(std::visit(
          [&](const auto& m) -> GpuMaterial {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, LambertMaterial>)
              return {to_vec4(m.albedo), uvec4(FACET_MATERIAL_LAMBERT, 0, 0, 0), vec4(0), uvec4(0)};
            else if constexpr (std::is_same_v<M, MicroflakeMaterial>)
              return {to_vec4(m.albedo), uvec4(FACET_MATERIAL_MICROFLAKE, static_cast<uint>(m.ndf), 0, 0),
                      vec4(static_cast<float>(m.param), 0, 0, 0), uvec4(0)};
            else if constexpr (std::is_same_v<M, DiffractionMaterial>)
              return {to_vec4(m.base_albedo), uvec4(FACET_MATERIAL_DIFFRACTION, diffraction_index++, 0, 0), vec4(0),
                      uvec4(0)};
            else if constexpr (std::is_same_v<M, ColormapTextureMaterial>)
              return {vec4(1), uvec4(FACET_MATERIAL_COLORMAP_TEXTURE, 0, 0, 0), vec4(0),
                      add_colormap_texture(textures, m, colormap_tables)};
            else if constexpr (std::is_same_v<M, MicrosurfaceMaterial>)
              return add_microsurface(textures, m);
            else
              static_assert(sizeof(M) == 0, "every material kind needs its GPU record");
          },
          material));
  };
  // The texels are written once, where the shader reads them: the buffer is made first, at the size
  // the materials will append (a 256^2 microsurface appends 11 MB), and where its memory is mapped and
  // host-cached (lavapipe) they are built in it; else in host memory reserved ahead, then uploaded.
  // filtered:table's tables are sized only as they are built, so with them the buffer comes last.
  vk::Buffer texels = [&] {
    std::size_t planned = 0;
    for (const Material& material : scene.materials) {
      if (const auto* t = std::get_if<ColormapTextureMaterial>(&material)) planned += colormap_texture_texels(*t);
      if (const auto* m = std::get_if<MicrosurfaceMaterial>(&material)) planned += microsurface_texels(*m);
    }
    if (colormap_tables) {
      textures.texels.reserve(planned);  // the tables, built on the way, may still grow it
      add_materials();
      return vk::Buffer::from(context, std::span<const vec4>(textures.texels));
    }
    vk::Buffer buffer = vk::Buffer::of<vec4>(context, planned);
    if (buffer.host_cached())
      textures.texels = TexelStore(std::span<vec4>(static_cast<vec4*>(buffer.mapped()), planned));
    else
      textures.texels.reserve(planned);
    add_materials();
    if (!textures.texels.in_place() && textures.texels.size() > 0)
      buffer.upload(textures.texels.data(), sizeof(vec4) * textures.texels.size());
    return buffer;
  }();

  Bvh bvh = build_bvh(scene.meshes);
  std::vector<GpuBvhNode> nodes(bvh.nodes.size());
  static_assert(sizeof(BvhNode) == sizeof(GpuBvhNode));
  if (!nodes.empty())  // a scene without meshes has no nodes; memcpy from null is undefined even for 0 bytes
    std::memcpy(nodes.data(), bvh.nodes.data(), nodes.size() * sizeof(GpuBvhNode));
  std::vector<GpuTriangle> triangles = flatten_triangles(scene, bvh);

  const GpuGlobals globals{};  // the camera block is written per frame by set_camera
  SceneBuffers buffers{
      vk::Buffer::from(context, std::span<const GpuGlobals>(&globals, 1)),
      vk::Buffer::from(context, std::span<const GpuPlane>(planes)),
      vk::Buffer::from(context, std::span<const GpuSphere>(spheres)),
      vk::Buffer::from(context, std::span<const GpuBvhNode>(nodes)),
      vk::Buffer::from(context, std::span<const GpuTriangle>(triangles)),
      vk::Buffer::from(context, std::span<const GpuMaterial>(materials)),
      vk::Buffer::from(context, std::span<const GpuTextureLevel>(textures.levels)),
      std::move(texels),
      vk::Buffer::from(context, std::span<const GpuColormap>(textures.colormaps)),
      vk::Buffer::from(context, std::span<const vec4>(textures.colormap_points)),
      uvec4(planes.size(), spheres.size(), nodes.size(), triangles.size()),
  };
  build_gpu_mips(context, buffers.texels, textures);
  return buffers;
}

}  // namespace facet::gpu
