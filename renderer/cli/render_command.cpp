// facet render SCENE -o OUT.exr: renders a scene on the Vulkan device to EXR (+ PNG preview).
#include <chrono>
#include <filesystem>
#include <future>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/frame_output.hpp"
#include "cli/idle_options.hpp"
#include "common/counted.hpp"
#include "common/error.hpp"
#include "common/phase_timings.hpp"
#include "common/progress.hpp"
#include "frames/frame_metadata.hpp"
#include "frames/prepared_frames.hpp"
#include "scene/scene_loader.hpp"
#include "vk/context.hpp"

namespace facet::cli {

namespace {

struct RenderOptions {
  std::filesystem::path scene;
  std::vector<std::string> overrides;  // --set
  DeviceOptions device;
  ResolutionOptions resolution;
  FrameOption frame;
  frames::FrameFile output;
  std::string method = "naive";
  std::string diffraction;  // empty: the diffraction materials' own "method"
  int wavelengths = 0;      // 0: the materials' own counts
  int taylor = 0;
  bool timings = false;  // --timings: print the phases
  std::string aov;       // --aov: comma list of auxiliary channels
  gpu::AdaptiveBudget adaptive;  // --adaptive-error, --adaptive-time
};

// --diffraction, --wavelengths and --taylor on top of --method (they win over a diffraction:M method).
gpu::RenderMethod render_method(const RenderOptions& options) {
  gpu::RenderMethod method = gpu::RenderMethod::parse(options.method);
  if (!options.diffraction.empty()) {
    method.diffraction.method = diffraction::parse_diffraction_method(options.diffraction);
    if (!method.diffraction.method)
      throw Error("--diffraction " + options.diffraction + ": must be one of spectral, preintegrated, orders");
  }
  method.diffraction.wavelengths = options.wavelengths;
  method.diffraction.taylor = options.taylor;
  method.aovs = parse_aovs(options.aov);
  if (method.aovs.error && !method.estimates_error())
    throw Error("--aov error: only --method filtered (or filtered:ss:K) estimates its error, not " + method.name());
  if ((options.adaptive.error || options.adaptive.time_ms) && method.adaptive_samples_per_axis == 0)
    throw Error("--adaptive-error and --adaptive-time budget --method filtered:adaptive, not " + method.name());
  method.adaptive = options.adaptive;
  return method;
}

// The diffraction options as the user gave them ("--wavelengths 16"), for idle_option_warnings().
std::vector<std::string> given_diffraction_options(const RenderOptions& options) {
  std::vector<std::string> given;
  if (options.method.starts_with("diffraction:")) given.push_back("--method " + options.method);
  if (!options.diffraction.empty()) given.push_back("--diffraction " + options.diffraction);
  if (options.wavelengths > 0) given.push_back("--wavelengths " + std::to_string(options.wavelengths));
  if (options.taylor > 0) given.push_back("--taylor " + std::to_string(options.taylor));
  return given;
}

// One line per phase on stderr, then the total: where the wall clock of `facet render` went.
void print_timings(const PhaseTimings& phases, double gpu_ms) {
  std::cerr << "facet: timings (wall ms):\n";
  for (const Phase& phase : phases.phases()) {
    std::cerr << "  " << phase.name << " " << phase.ms;
    if (phase.name == "render") std::cerr << " (device " << gpu_ms << ")";
    std::cerr << "\n";
  }
  std::cerr << "  total " << phases.total_ms() << "\n";
}

int run_render(const RenderOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  PhaseTimings phases;
  // The device is created while the scene loads: neither needs the other, and each takes tens of ms.
  std::future<std::unique_ptr<vk::Context>> creating = std::async(std::launch::async, [&options] {
    return std::make_unique<vk::Context>(vk::ContextOptions{options.device.device, options.device.validation});
  });
  Scene scene = timed(&phases, "load", [&] { return load_scene(options.scene, options.overrides); });
  options.frame.apply(scene);
  const auto [width, height] = options.resolution.resolve(scene.camera);
  const gpu::RenderMethod method = render_method(options);
  for (const std::string& warning : idle_option_warnings(scene, method, given_diffraction_options(options)))
    std::cerr << warning << "\n";
  // The part of the device's creation the load did not hide.
  const std::unique_ptr<vk::Context> device = timed(&phases, "device", [&] { return creating.get(); });
  vk::Context& context = *device;
  frames::PreparedFrames prepared(scene, method, &context);
  phases.add(prepared.preparation());
  ProgressBar progress("render", gpu::tile_count(width, height));
  frames::FrameRequest request;
  request.frame = options.frame.frame;
  request.since = start;
  request.progress = [&](std::int64_t done, std::int64_t) { progress.update(done); };
  frames::Frame frame = timed(&phases, "render", [&] { return prepared.render(scene.camera, width, height, request); });
  progress.finish();
  frames::add_phase_timings(frame.metadata, phases);
  timed(&phases, "write", [&] { frames::write_frame(options.output, frame.image, frame.metadata); });
  std::cerr << "facet: rendered " << width << "x" << height << " in " << frame.wall_ms << " ms (GPU " << frame.gpu_ms
            << " ms in " << counted(gpu::tile_count(width, height), "tile") << ") on " << context.info().name << " -> "
            << options.output.path.string() << "\n";
  if (options.timings) print_timings(phases, frame.gpu_ms);
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("render", "Render a scene on the Vulkan device to an OpenEXR file");
  auto options = std::make_shared<RenderOptions>();
  command->add_option("scene", options->scene, "Scene file (JSON, or glTF 2.0 .gltf/.glb; see scenes/README.md)")->required();
  add_device_options(*command, options->device);
  command
      ->add_option("--method", options->method,
                   "How sub-pixel detail becomes a pixel: naive, mip, colormip, ss:K (K x K rays), filtered, "
                   "filtered:table; M:ss:K runs footprint method M per stratum of ss:K (filtered:ss:2); "
                   "filtered:adaptive[:K] adds up to K x K strata (K = 8) where filtered's estimated error is largest, "
                   "as many as its kind of error needs")
      ->capture_default_str();
  command
      ->add_option("--adaptive-error", options->adaptive.error,
                   "filtered:adaptive refines every pixel whose estimated error (the error AOV) exceeds this "
                   "(default: the refinements that remove the most estimated error, within the work of two more strata "
                   "per pixel)")
      ->check(CLI::PositiveNumber);
  command
      ->add_option("--adaptive-time", options->adaptive.time_ms,
                   "filtered:adaptive refines, largest estimated error first, until the frame has taken this many "
                   "ms of device time (the image then depends on the host's speed)")
      ->check(CLI::PositiveNumber);
  command->add_option("--diffraction", options->diffraction,
                      "How diffraction materials become colours: spectral, preintegrated or orders (default: each "
                      "material's \"method\")");
  command
      ->add_option("--wavelengths", options->wavelengths,
                   "Wavelength samples of the diffraction materials' colour integral (default: from their tolerance)")
      ->check(CLI::Range(2, 4096));
  command->add_option("--taylor", options->taylor, "Taylor terms of the diffraction BRDF (default: from the tolerance)")
      ->check(CLI::Range(1, 64));
  command->add_option("--aov", options->aov,
                      "Auxiliary channels to write, a comma list of depth (Z), normal (N.X N.Y N.Z), uv (U V), "
                      "error (--method filtered's per-pixel error estimate); docs/aov.md");
  command->add_flag("--timings", options->timings,
                    "Print the wall time of each phase (load, device, upload, diffraction, pipeline, jit, render, "
                    "write); they are also in the EXR metadata as facet:phase:<name>_ms");
  add_set_option(*command, options->overrides, "the scene");
  add_resolution_options(*command, options->resolution);
  add_frame_option(*command, options->frame);
  add_output_options(*command, options->output);
  command->callback([&action, options] { action = [options] { return run_render(*options); }; });
}

}  // namespace facet::cli
