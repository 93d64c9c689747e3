// A scene flattened into the GPU's storage buffers (layouts in shaders/layout/scene_layout.glsl).
#pragma once

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
};

// The camera block of GpuGlobals for an image of width x height (the scene's own
// resolution may be overridden on the command line).
GpuGlobals make_globals(const Scene& scene, int width, int height);

SceneBuffers upload_scene(vk::Context& context, const Scene& scene, int width, int height);

}  // namespace facet::gpu
