// Renders the frames of one scene with one method for `facet batch`: the GPU pass is built once
// (buffers, MIP chains, pipeline) and serves every frame; "reference" is the CPU reference.
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "batch/job.hpp"
#include "cli/commands.hpp"
#include "gpu/direct_pass.hpp"
#include "image/exr_io.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

namespace facet::cli {

// One Vulkan device for the whole batch, created on first use (a batch of reference frames, or one
// with nothing left to do, never touches Vulkan).
class SharedDevice {
 public:
  explicit SharedDevice(DeviceOptions options) : options_(std::move(options)) {}
  vk::Context& context();

 private:
  DeviceOptions options_;
  std::unique_ptr<vk::Context> context_;
};

struct RenderedFrame {
  Image image;
  ExrMetadata metadata;  // reproducible: no timings, so equal inputs give equal bytes
};

class BatchRenderer {
 public:
  // Parses `method` and prepares it for `scene` (which must outlive this); throws facet::Error if the
  // method is unknown or cannot render the scene. `cancel` stops a reference frame between tiles.
  BatchRenderer(const Scene& scene, const std::string& method, const batch::Job& job, SharedDevice& device,
                const std::atomic<bool>* cancel);
  RenderedFrame render(int frame);

 private:
  const Scene* scene_;
  const batch::Job* job_;
  const std::atomic<bool>* cancel_;
  vk::Context* context_ = nullptr;
  std::optional<gpu::RenderMethod> method_;  // empty: the reference
  std::unique_ptr<gpu::DirectPass> pass_;
};

}  // namespace facet::cli
