// facet render SCENE -o OUT.exr: renders a scene on the Vulkan device to EXR (+ PNG preview).
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "cli/frame_output.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"
#include "gpu/direct_pass.hpp"
#include "scene/scene_loader.hpp"
#include "vk/context.hpp"

namespace facet::cli {

namespace {

struct RenderOptions {
  std::filesystem::path scene;
  DeviceOptions device;
  ResolutionOptions resolution;
  OutputOptions output;
  std::string method = "naive";
};

int run_render(const RenderOptions& options) {
  auto start = std::chrono::steady_clock::now();
  Scene scene = load_scene(options.scene);
  auto [width, height] = options.resolution.resolve(scene.camera);
  const gpu::RenderMethod method = gpu::RenderMethod::parse(options.method);
  vk::Context context({options.device.device, options.device.validation});
  ProgressBar progress("render", gpu::tile_count(width, height));
  gpu::RenderStats stats;
  Image image = gpu::render_direct(context, scene, width, height, method, &stats,
                                    [&](int done, int) { progress.update(done); });
  progress.finish();
  if (context.validation_message_count() > 0)
    throw Error("Vulkan validation reported " + std::to_string(context.validation_message_count()) +
                " messages; no image written");
  double wall_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  ExrMetadata metadata = frame_metadata(scene, method.name(), method.samples_per_axis * method.samples_per_axis, context.info().name, stats.gpu_ms, wall_ms);
  write_frame(options.output, image, metadata);
  std::cerr << "facet: rendered " << width << "x" << height << " in " << wall_ms << " ms (GPU "
            << stats.gpu_ms << " ms in " << stats.tiles << " tiles) on " << context.info().name
            << " -> " << options.output.path.string() << "\n";
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("render", "Render a scene on the Vulkan device to an OpenEXR file");
  auto options = std::make_shared<RenderOptions>();
  command->add_option("scene", options->scene, "Scene file (JSON, see scenes/README.md)")->required();
  add_device_options(*command, options->device);
  command->add_option("--method", options->method,
                      "How sub-pixel detail becomes a pixel: naive, mip, colormip, ss:K (K x K rays), filtered")
      ->capture_default_str();
  add_resolution_options(*command, options->resolution);
  add_output_options(*command, options->output);
  command->callback([&action, options] { action = [options] { return run_render(*options); }; });
}

}  // namespace facet::cli
