#include "frames/prepared_frames.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/counted.hpp"
#include "common/error.hpp"
#include "cpu/reference_renderer.hpp"
#include "frames/frame_metadata.hpp"

namespace facet::frames {

namespace {

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::pair<int, int> frame_size(const Camera& camera, int width, int height) {
  const double aspect = double(camera.height) / camera.width;
  auto at_least_1 = [](double side) { return std::max(1, static_cast<int>(std::lround(side))); };
  if (width > 0) return {width, height > 0 ? height : at_least_1(width * aspect)};
  if (height > 0) return {at_least_1(height / aspect), height};
  return {camera.width, camera.height};
}

PreparedFrames::PreparedFrames(const Scene& scene, FrameMethod method, vk::Context* context)
    : scene_(&scene), method_(std::move(method)), context_(context) {
  const auto* gpu_method = std::get_if<gpu::RenderMethod>(&method_);
  if (!gpu_method) return;
  if (!context_) throw Error("method " + gpu_method->name() + " needs a Vulkan device");
  validation_messages_ = context_->validation_message_count();
  pass_ = std::make_unique<gpu::DirectPass>(*context_, scene, *gpu_method, gpu::kDefaultTileSize, &preparation_);
}

Frame PreparedFrames::render(const Camera& camera, int width, int height, const FrameRequest& request) {
  const auto start = request.since.value_or(std::chrono::steady_clock::now());
  Frame frame;
  gpu::RenderStats stats;
  frame.image = pass_ ? render_gpu(camera, width, height, request, stats) : render_reference(camera, width, height, request);
  frame.gpu_ms = stats.gpu_ms;
  frame.wall_ms = ms_since(start);
  frame.metadata = metadata();
  add_standard_attributes(frame.metadata, camera, width, height, samples_per_pixel());
  if (request.timings) add_timings(frame.metadata, pass_ ? std::optional(frame.gpu_ms) : std::nullopt, frame.wall_ms);
  if (request.timings && pass_) add_table_cache_metadata(frame.metadata, pass_->diffraction());
  add_frame_number(frame.metadata, request.frame);
  if (const auto* gpu_method = std::get_if<gpu::RenderMethod>(&method_); gpu_method && gpu_method->adaptive_samples_per_axis)
    frame.metadata["facet:refined_pixels"] = static_cast<std::int64_t>(stats.refined_pixels);
  return frame;
}

Image PreparedFrames::render_gpu(const Camera& camera, int width, int height, const FrameRequest& request,
                                 gpu::RenderStats& stats) {
  gpu::TileProgress progress;
  if (request.progress) progress = [&](int done, int total) { request.progress(done, total); };
  Image image = pass_->render(camera, width, height, &stats, progress);
  const std::uint32_t messages = context_->validation_message_count() - validation_messages_;
  validation_messages_ = context_->validation_message_count();
  if (messages > 0) throw Error("Vulkan validation reported " + counted(messages, "message") + "; no image written");
  return image;
}

Image PreparedFrames::render_reference(const Camera& camera, int width, int height, const FrameRequest& request) const {
  const auto& reference = std::get<ReferenceMethod>(method_);
  cpu::ReferenceOptions options;
  options.width = width;
  options.height = height;
  options.grid = reference.grid;
  options.seed = static_cast<std::uint64_t>(reference.seed);
  options.threads = reference.threads;
  options.aovs = reference.aovs;
  options.cancel = request.cancel;
  options.progress = request.progress;
  Scene framed = *scene_;  // the reference renders the scene's own camera
  framed.camera = camera;
  return cpu::render_reference(framed, options);
}

std::int64_t PreparedFrames::samples_per_pixel() const {
  if (const auto* method = std::get_if<gpu::RenderMethod>(&method_))
    return method->samples_per_axis * method->samples_per_axis;
  const auto& reference = std::get<ReferenceMethod>(method_);
  return static_cast<std::int64_t>(reference.grid) * reference.grid;
}

ExrMetadata PreparedFrames::metadata() const {
  if (const auto* method = std::get_if<gpu::RenderMethod>(&method_)) {
    ExrMetadata metadata = frame_metadata(*scene_, method->name(), samples_per_pixel(), context_->info().name);
    add_diffraction_metadata(metadata, pass_->diffraction());
    return metadata;
  }
  const auto& reference = std::get<ReferenceMethod>(method_);
  ExrMetadata metadata = frame_metadata(*scene_, "reference", samples_per_pixel(), "cpu");
  add_reference_metadata(metadata, reference);
  return metadata;
}

}  // namespace facet::frames
