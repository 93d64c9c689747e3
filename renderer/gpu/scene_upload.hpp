// A scene flattened into the GPU's storage buffers (layouts in shaders/layout/scene_layout.glsl).
#pragma once

#include <vector>

#include "gpu/scene_layout.hpp"
#include "scene/scene.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

struct SceneBuffers {
  vk::Buffer globals;
  vk::Buffer planes;
  vk::Buffer spheres;
  vk::Buffer nodes;
  vk::Buffer triangles;
  vk::Buffer materials;
  vk::Buffer texture_levels;
  vk::Buffer texels;
  vk::Buffer colormaps;
  vk::Buffer colormap_points;
  uvec4 counts;  // planes, spheres, BVH nodes, triangles: GpuGlobals::counts

  // Slots 0..FACET_RENDER_SCENE_BINDING_COUNT-1 of the direct pass, each buffer at its named slot
  // (shaders/layout/render_layout.glsl), `pixels` at FACET_RENDER_BINDING_PIXELS.
  std::vector<const vk::Buffer*> bindings(const vk::Buffer& pixels) const;
  // How the shaders bind those slots (render/scene_bindings.glsl): the globals as a uniform buffer,
  // the pixels (written) as a storage buffer, every other slot as a texel buffer.
  static std::vector<vk::BufferKind> binding_kinds();
  // Writes the camera block of the globals for `camera` and an image of width x height (the
  // scene's own camera and resolution may be overridden per frame).
  void set_camera(const Scene& scene, const Camera& camera, int width, int height);
};

// colormap_tables: also build and upload each colour map's prefiltered table (`filtered:table`).
SceneBuffers upload_scene(vk::Context& context, const Scene& scene, bool colormap_tables = false);

}  // namespace facet::gpu
