// "Method -> prepared renderer -> image + metadata", for every caller (`facet render`, `reference`,
// `batch`, `bench`): a GPU method builds its direct pass once (buffers, MIP chains, pipeline) and any
// number of frames render from it, from any camera; the CPU reference has nothing to prepare.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "common/phase_timings.hpp"
#include "frames/frame_method.hpp"
#include "gpu/direct_pass.hpp"
#include "image/exr_io.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

namespace facet::frames {

// Tiles done, tiles in all.
using FrameProgress = std::function<void(std::int64_t done, std::int64_t total)>;

struct FrameRequest {
  int frame = -1;       // the camera_path frame the camera shows, recorded as facet:frame; -1: the still camera
  bool timings = true;  // false: no facet:gpu_ms / facet:render_ms, so equal inputs give equal bytes (batch)
  std::optional<std::chrono::steady_clock::time_point> since;  // start of facet:render_ms; default: the call
  FrameProgress progress;
  const std::atomic<bool>* cancel = nullptr;  // stops a reference frame between tiles (it then throws)
};

struct Frame {
  Image image;
  ExrMetadata metadata;
  double gpu_ms = 0.0;   // the device time; 0 for the CPU reference, whose file has no facet:gpu_ms
  double wall_ms = 0.0;  // since FrameRequest::since
};

// The image size: `width` and `height` where > 0; a side not given follows the camera's aspect
// (rounded, at least 1 pixel), and neither given is the camera's own size.
std::pair<int, int> frame_size(const Camera& camera, int width, int height);

class PreparedFrames {
 public:
  // Prepares `method` for `scene`, which must outlive this. A GPU method renders on `context` (required
  // then; the reference ignores it). Throws facet::Error if the method cannot render the scene.
  PreparedFrames(const Scene& scene, FrameMethod method, vk::Context* context);

  // Throws facet::Error if Vulkan validation reported messages since the previous frame (or the
  // preparation): no image is returned then.
  Frame render(const Camera& camera, int width, int height, const FrameRequest& request = {});

  // The preparation's phases (DirectPass: upload, diffraction, pipeline, jit); none for the reference.
  const PhaseTimings& preparation() const { return preparation_; }

 private:
  Image render_gpu(const Camera& camera, int width, int height, const FrameRequest& request, gpu::RenderStats& stats);
  Image render_reference(const Camera& camera, int width, int height, const FrameRequest& request) const;
  ExrMetadata metadata() const;  // the facet:* attributes of the method
  std::int64_t samples_per_pixel() const;

  const Scene* scene_;
  FrameMethod method_;
  vk::Context* context_;
  PhaseTimings preparation_;
  std::uint32_t validation_messages_ = 0;  // seen up to the preparation or the previous frame
  std::unique_ptr<gpu::DirectPass> pass_;  // GPU methods only
};

}  // namespace facet::frames
