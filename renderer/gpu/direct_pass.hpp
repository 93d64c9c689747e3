// The direct-lighting GPU pass: one primary ray per pixel, each material's direct lighting from
// the directional light (with a shadow ray) plus the ambient fill.
#pragma once

#include <functional>

#include "gpu/render_method.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

struct RenderStats {
  double gpu_ms = 0.0;  // sum of the tiles' GPU timestamps
  int tiles = 0;
};

constexpr int kDefaultTileSize = 256;

// How many tiles (= submissions) an image of width x height is split into.
int tile_count(int width, int height, int tile_size = kDefaultTileSize);

// Progress callback: tiles done, tiles in all.
using TileProgress = std::function<void(int, int)>;

// Renders `scene` at width x height with `method` in square tiles of `tile_size` pixels, one
// submission per tile, so no single submission runs for seconds.
Image render_direct(vk::Context& context, const Scene& scene, int width, int height, const RenderMethod& method = {},
                    RenderStats* stats = nullptr, const TileProgress& progress = {},
                    int tile_size = kDefaultTileSize);

}  // namespace facet::gpu
