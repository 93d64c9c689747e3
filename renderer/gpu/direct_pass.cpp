#include "gpu/direct_pass.hpp"

#include <algorithm>
#include <array>
#include <variant>
#include <vector>

#include "common/error.hpp"
#include "gpu/scene_upload.hpp"
#include "render_direct.spv.h"
#include "vk/kernel.hpp"

namespace facet::gpu {

namespace {
constexpr uint32_t kWorkgroup = 8;  // local_size_x/y of render_direct.comp

template <class M>
bool uses(const Scene& scene) {
  for (const Material& m : scene.materials)
    if (std::holds_alternative<M>(m)) return true;
  return false;
}
}  // namespace

int tile_count(int width, int height, int tile_size) {
  return ((width + tile_size - 1) / tile_size) * ((height + tile_size - 1) / tile_size);
}

Image render_direct(vk::Context& context, const Scene& scene, int width, int height, const RenderMethod& method,
                    RenderStats* stats, const TileProgress& progress, int tile_size) {
  if (width <= 0 || height <= 0) throw Error("image size must be positive");
  SceneBuffers buffers = upload_scene(context, scene, width, height);
  // One tile's pixels at a time: frames of any size stay within the storage-buffer range.
  vk::Buffer pixels(context, sizeof(vec4) * static_cast<uint64_t>(tile_size) * tile_size);
  vk::Kernel kernel(context, {.name = "render_direct",
                              .spirv = render_direct_spv,
                              .buffer_count = 11,
                              .push_constant_bytes = sizeof(GpuTile),
                              .specialization = {{0, uses<MicroflakeMaterial>(scene) ? 1u : 0u},
                                                 {1, uses<ColormapTextureMaterial>(scene) ? 1u : 0u},
                                                 {2, static_cast<uint32_t>(method.texture)},
                                                 {3, static_cast<uint32_t>(method.samples_per_axis)}}});
  const std::array<const vk::Buffer*, 11> bindings = {
      &buffers.globals,   &buffers.planes,         &buffers.spheres, &buffers.nodes,     &buffers.triangles,
      &buffers.materials, &pixels,                 &buffers.texture_levels, &buffers.texels, &buffers.colormaps,
      &buffers.colormap_points};
  Image image(width, height);
  std::vector<vec4> tile_rgba(static_cast<size_t>(tile_size) * tile_size);
  RenderStats local;
  const int tiles = tile_count(width, height, tile_size);
  for (int y0 = 0; y0 < height; y0 += tile_size)
    for (int x0 = 0; x0 < width; x0 += tile_size) {
      const int w = std::min(tile_size, width - x0), h = std::min(tile_size, height - y0);
      GpuTile tile{uvec4(x0, y0, w, h)};
      glm::uvec3 groups((w + kWorkgroup - 1) / kWorkgroup, (h + kWorkgroup - 1) / kWorkgroup, 1);
      local.gpu_ms += kernel.dispatch(bindings, &tile, groups);
      pixels.download(tile_rgba.data(), sizeof(vec4) * static_cast<size_t>(w) * h);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) image.set(x0 + x, y0 + y, glm::vec3(tile_rgba[static_cast<size_t>(y) * w + x]));
      ++local.tiles;
      if (progress) progress(local.tiles, tiles);
    }
  if (stats) *stats = local;
  return image;
}

}  // namespace facet::gpu
