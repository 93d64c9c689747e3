#include "cli/batch_renderer.hpp"

#include "cli/frame_output.hpp"
#include "common/error.hpp"
#include "cpu/reference_renderer.hpp"
#include "scene/camera_path.hpp"

namespace facet::cli {

vk::Context& SharedDevice::context() {
  if (!context_) context_ = std::make_unique<vk::Context>(vk::ContextOptions{options_.device, options_.validation});
  return *context_;
}

BatchRenderer::BatchRenderer(const Scene& scene, const std::string& method, const batch::Job& job,
                             SharedDevice& device, const std::atomic<bool>* cancel)
    : scene_(&scene), job_(&job), cancel_(cancel) {
  if (method == "reference") return;
  method_ = gpu::RenderMethod::parse(method);
  context_ = &device.context();
  pass_ = std::make_unique<gpu::DirectPass>(*context_, scene, *method_);
}

RenderedFrame BatchRenderer::render(int frame) {
  Scene framed = *scene_;  // the metadata names the scene; the camera is the frame's
  framed.camera = camera_at(*scene_, frame);
  const auto [width, height] = ResolutionOptions{job_->width, job_->height}.resolve(framed.camera);
  RenderedFrame out;
  if (method_) {
    const auto messages = context_->validation_message_count();
    out.image = pass_->render(framed.camera, width, height);
    if (context_->validation_message_count() != messages) throw Error("Vulkan validation reported messages; no image written");
    out.metadata = frame_metadata(framed, method_->name(), method_->samples_per_axis * method_->samples_per_axis,
                                  context_->info().name, 0.0, 0.0);
  } else {
    cpu::ReferenceOptions options;
    options.width = width;
    options.height = height;
    options.grid = job_->grid;
    options.seed = static_cast<std::uint64_t>(job_->seed);
    options.cancel = cancel_;
    out.image = cpu::render_reference(framed, options);
    out.metadata = frame_metadata(framed, "reference", static_cast<std::int64_t>(job_->grid) * job_->grid, "cpu", 0.0, 0.0);
    add_reference_metadata(out.metadata, job_->grid, job_->seed);
  }
  out.metadata.erase("facet:gpu_ms");  // timings go to the manifest
  out.metadata.erase("facet:render_ms");
  FrameOption{frame}.annotate(out.metadata);
  return out;
}

}  // namespace facet::cli
