#include "gpu/lambert_pass.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "common/error.hpp"
#include "gpu/scene_upload.hpp"
#include "render_lambert.spv.h"
#include "vk/kernel.hpp"

namespace facet::gpu {

namespace {
constexpr uint32_t kWorkgroup = 8;  // local_size_x/y of render_lambert.comp
}

int tile_count(int width, int height, int tile_size) {
  return ((width + tile_size - 1) / tile_size) * ((height + tile_size - 1) / tile_size);
}

Image render_lambert(vk::Context& context, const Scene& scene, int width, int height,
                     RenderStats* stats, const TileProgress& progress, int tile_size) {
  if (width <= 0 || height <= 0) throw Error("image size must be positive");
  SceneBuffers buffers = upload_scene(context, scene, width, height);
  const uint64_t pixel_bytes = sizeof(vec4) * static_cast<uint64_t>(width) * height;
  vk::Buffer pixels(context, pixel_bytes);
  vk::Kernel kernel(context, {.name = "render_lambert",
                              .spirv = render_lambert_spv,
                              .buffer_count = 7,
                              .push_constant_bytes = sizeof(GpuTile),
                              .specialization = {}});
  const std::array<const vk::Buffer*, 7> bindings = {&buffers.globals, &buffers.planes,
                                                     &buffers.spheres, &buffers.nodes,
                                                     &buffers.triangles, &buffers.materials, &pixels};
  const int tiles_x = (width + tile_size - 1) / tile_size;
  const int tiles_y = (height + tile_size - 1) / tile_size;
  RenderStats local;
  for (int ty = 0; ty < tiles_y; ++ty)
    for (int tx = 0; tx < tiles_x; ++tx) {
      GpuTile tile{uvec4(tx * tile_size, ty * tile_size, std::min(tile_size, width - tx * tile_size),
                         std::min(tile_size, height - ty * tile_size))};
      glm::uvec3 groups((tile.rect.z + kWorkgroup - 1) / kWorkgroup,
                        (tile.rect.w + kWorkgroup - 1) / kWorkgroup, 1);
      local.gpu_ms += kernel.dispatch(bindings, &tile, groups);
      ++local.tiles;
      if (progress) progress(local.tiles, tiles_x * tiles_y);
    }
  if (stats) *stats = local;

  std::vector<vec4> rgba(static_cast<size_t>(width) * height);
  pixels.download(rgba.data(), pixel_bytes);
  Image image(width, height);
  for (size_t i = 0; i < rgba.size(); ++i) image.set(i, glm::vec3(rgba[i]));
  return image;
}

}  // namespace facet::gpu
