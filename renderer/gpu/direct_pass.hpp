// The direct-lighting GPU pass: one primary ray per pixel, each material's direct lighting from
// the directional light (with a shadow ray) plus the ambient fill.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <future>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "common/phase_timings.hpp"
#include "gpu/diffraction_upload.hpp"
#include "gpu/pixel_coverage.hpp"
#include "gpu/render_method.hpp"
#include "gpu/scene_upload.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/kernel.hpp"

namespace facet::gpu {

struct RenderStats {
  double gpu_ms = 0.0;  // sum of the tiles' GPU timestamps
  int tiles = 0;
  std::size_t refined_pixels = 0;  // filtered:adaptive: the pixels rendered again with K x K strata
};

constexpr int kDefaultTileSize = 256;
constexpr int kMaxTileSize = 2040;  // (2040 / 8)^2 workgroups: within gpu::kMaxTileBlocks (direct_pass.cpp checks)

// How many tiles (= submissions) an image of width x height is split into.
int tile_count(int width, int height, int tile_size = kDefaultTileSize);

// Progress callback: tiles done, tiles in all.
using TileProgress = std::function<void(int, int)>;

// The pass prepared for one scene and method: its buffers, precomputed data (MIP chains) and
// pipeline are built once, then any number of frames render from any camera (precompute once,
// render many). Holds a reference to `scene`, which must outlive it.
class DirectPass {
 public:
  // `timings`, when given, receives the preparation's phases: upload (textures, MIP and moment chains),
  // diffraction (tables), pipeline (creation) and jit (lavapipe compiles on the first dispatch, made here).
  DirectPass(vk::Context& context, const Scene& scene, const RenderMethod& method = {},
             int tile_size = kDefaultTileSize, PhaseTimings* timings = nullptr);

  // Renders width x height from `camera` in square tiles of `tile_size` pixels, one submission
  // per tile (K^2 for ss:K, one per stratum), so no single submission runs for seconds.
  Image render(const Camera& camera, int width, int height, RenderStats* stats = nullptr,
               const TileProgress& progress = {});

  // The diffraction method, wavelength and Taylor-term counts this pass renders with (metadata).
  const DiffractionBuffers& diffraction() const { return diffraction_; }

 private:
  // What the pass settles before it uploads or compiles anything: a sample's shadow rays through height fields
  // (0: none traced) and the nodes each may visit, checked against the tracer's loop bound
  // (gpu/heightfield_trace_bound.hpp), the diffraction's plan (its specialization known before the tables are
  // read), and the code the program compiles in (gpu/direct_pass_variant.hpp: the scene's families, the method's
  // and, under `orders`, whether the plan falls back to the spectral path), which chooses the variant and its
  // specialization alike.
  struct Plan {
    int field_shadow_rays = 0;
    std::int64_t field_shadow_nodes = 0;
    DiffractionPlan diffraction;
    uint32_t code = 0;
  };
  static Plan make_plan(vk::Context& context, const Scene& scene, const RenderMethod& method);
  // The constructor's work, once planned.
  DirectPass(vk::Context& context, const Scene& scene, const RenderMethod& method, int tile_size, PhaseTimings* timings,
             Plan plan);
  std::vector<const vk::Buffer*> bindings() const;  // scene buffers, pixels, diffraction buffers
  // Dispatches `tile` in `groups` workgroups and, where the pass queues filtered's microsurface statistics, a
  // second dispatch that shades the queue (render/microsurface_statistics_queue.glsl); their device ms.
  double dispatch(std::span<const vk::Buffer* const> bindings, GpuTile tile, glm::uvec3 groups);
  // Renders stratum `stratum` of ss:K into pixels_ for the tile's w x h pixels at (x0, y0); its device ms.
  double dispatch_tile(std::span<const vk::Buffer* const> bindings, int x0, int y0, int w, int h, int stratum);
  // Renders the first `count` entries of pixel_list_ (each a pixel and one of its K x K strata) into
  // pixels_, one entry a slot; its device ms.
  double dispatch_list(std::span<const vk::Buffer* const> bindings, std::size_t count, int k);
  // Renders `pixels` again with K x K strata each, as many pixels a dispatch as pixels_ holds strata for,
  // into `image` and `aovs` (the error with the first pass's edge term over K); its device ms.
  double refine_group(std::span<const vk::Buffer* const> bindings, std::span<const uint32_t> pixels, int k,
                      Image& image, std::vector<AovPixel>& aovs, std::span<const float> edge);
  // GpuTile::list.y of a dispatch: 1 leaves the texture's error estimate out (another colour-map integral
  // per tap). Only the error channel needs it, and filtered:adaptive's first pass, which ranks by it.
  uint32_t skips_estimate(bool refining) const;
  // filtered:adaptive: renders the pixels the budget buys (gpu/adaptive_refinement.hpp: from aovs[i].error
  // and the first pass's edge term `edge`) again, each with its K x K strata, into `image` and `aovs`;
  // `stats` holds the first pass's time, spent on `dispatched` of the pixels (the rest were background).
  void refine(std::span<const vk::Buffer* const> bindings, Image& image, std::vector<AovPixel>& aovs,
              std::span<const float> edge, RenderStats& stats, std::size_t dispatched);

  const Scene* scene_;
  SceneBounds bounds_;  // what each frame's tiles are cut to (gpu/pixel_coverage.hpp)
  std::string method_name_;
  int field_shadow_rays_;            // Plan's, for each frame's check of its camera ray
  std::int64_t field_shadow_nodes_;  // the same
  int tile_size_;
  int samples_per_axis_;  // ss:K: K^2 dispatches per tile
  AovSet aovs_;           // the auxiliary channels each frame carries
  int adaptive_samples_per_axis_;  // filtered:adaptive's largest K (0: not adaptive)
  AdaptiveBudget adaptive_budget_;
  bool writes_aovs_;      // the pass accumulates the auxiliary values (asked for, or filtered:adaptive's estimate)
  bool counts_work_;      // the pixels hold their samples' summed work, not colours (gpu/work_per_pixel.hpp)
  // The pipeline, compiled on a thread of its own while the diffraction tables are read and the textures
  // upload (lavapipe's pipeline creation is CPU work of its own; the table read is one file, the upload
  // mostly waits on small dispatches).
  std::future<std::unique_ptr<vk::Kernel>> compiling_;
  std::future<std::unique_ptr<vk::Kernel>> compiling_statistics_;  // the queue's pipeline, where one is queued
  DiffractionBuffers diffraction_;
  SceneBuffers buffers_;
  int list_capacity_;  // filtered:adaptive: the strata a dispatch of the refinement renders at most
  vk::Buffer pixels_;  // one tile's pixels: frames of any size stay within the storage-buffer range
  vk::Buffer pixel_list_;  // filtered:adaptive: up to list_capacity_ strata (pixel positions) to render
  vk::Buffer statistics_queue_;                    // filtered on traced microsurfaces: a dispatch's queued statistics
  std::unique_ptr<vk::Kernel> statistics_kernel_;  // the queue's dispatch (null: none queued), set with kernel_
  std::unique_ptr<vk::Kernel> kernel_;
};

// One frame from the scene's own camera: DirectPass(context, scene, method, tile_size).render(...).
Image render_direct(vk::Context& context, const Scene& scene, int width, int height, const RenderMethod& method = {},
                    RenderStats* stats = nullptr, const TileProgress& progress = {}, int tile_size = kDefaultTileSize);

}  // namespace facet::gpu
