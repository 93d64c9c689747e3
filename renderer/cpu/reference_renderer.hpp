// The reference renderer (`facet reference`): per pixel an N×N jittered grid of primary rays, box
// filtered, every texture at its finest level (bilinear), the colour map applied per sample, and
// microsurfaces traced as real height fields (docs/reference.md).
//
// Deterministic: the jitter of sample s of pixel p is a hash of (seed, p, s) and each pixel sums
// its samples in a fixed order, so the image does not depend on the thread count.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>

#include <glm/glm.hpp>

#include "image/aov.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

namespace facet::cpu {

struct ReferenceOptions {
  int width = 0, height = 0;  // image size, > 0
  int grid = 32;              // N: N×N samples per pixel, in [1, 4096]
  std::uint64_t seed = 1;
  bool jitter = true;  // false: the N×N sub-pixel centres (grid 1: the pixel centre)
  int threads = 0;     // 0: all cores
  int tile_size = 16;
  AovSet aovs{};  // depth, normal, uv written as channels (error is refused: it is a fast method's)
  const std::atomic<bool>* cancel = nullptr;  // set (e.g. by SIGINT) to stop between tiles
  std::function<void(std::int64_t tiles_done, std::int64_t tiles_total)> progress;  // called serialised
};

// The jitter of sample `sample` of pixel `pixel`: a point of [0, 1)², from a counter-based hash.
glm::dvec2 reference_jitter(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample);

// Throws facet::Error for invalid options, and "interrupted; no file written" once `cancel` is set.
Image render_reference(const Scene& scene, const ReferenceOptions& options);

}  // namespace facet::cpu
