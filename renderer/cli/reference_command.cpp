// facet reference SCENE -o REF.exr: the CPU reference image (docs/reference.md), to EXR + PNG preview.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/frame_output.hpp"
#include "common/interrupt.hpp"
#include "common/progress.hpp"
#include "frames/prepared_frames.hpp"
#include "scene/scene_loader.hpp"

namespace facet::cli {

namespace {

struct ReferenceCommandOptions {
  std::filesystem::path scene;
  std::vector<std::string> overrides;  // --set
  ResolutionOptions resolution;
  FrameOption frame;
  frames::FrameFile output;
  frames::ReferenceMethod reference;
  std::string aov;  // --aov
};

int run_reference(const ReferenceCommandOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Scene scene = load_scene(options.scene, options.overrides);
  options.frame.apply(scene);
  const auto [width, height] = options.resolution.resolve(scene.camera);
  frames::ReferenceMethod method = options.reference;
  method.aovs = parse_aovs(options.aov);  // error is refused by the reference renderer

  frames::PreparedFrames prepared(scene, method, nullptr);
  std::unique_ptr<ProgressBar> progress;
  frames::FrameRequest request;
  request.frame = options.frame.frame;
  request.since = start;
  request.cancel = &stop_on_interrupt();  // polled between rows, then throws: no file is written
  request.progress = [&](std::int64_t done, std::int64_t total) {
    if (!progress) progress = std::make_unique<ProgressBar>("reference", total);
    progress->update(done);
  };
  const frames::Frame frame = prepared.render(scene.camera, width, height, request);
  if (progress) progress->finish();

  frames::write_frame(options.output, frame.image, frame.metadata);
  const int grid = options.reference.grid;
  const double samples = static_cast<double>(width) * height * grid * grid;
  std::cerr << "facet: reference " << width << "x" << height << ", grid " << grid << "x" << grid << " in "
            << frame.wall_ms << " ms (" << samples / (frame.wall_ms * 1e3) << " M samples/s) -> "
            << options.output.path.string() << "\n";
  return 0;
}

}  // namespace

void add_reference_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("reference", "Render the CPU reference image of a scene to an OpenEXR file");
  auto options = std::make_shared<ReferenceCommandOptions>();
  command->add_option("scene", options->scene, "Scene file (JSON, or glTF 2.0 .gltf/.glb; see scenes/README.md)")->required();
  command->add_option("--grid", options->reference.grid, "N: an N x N jittered grid of primary rays per pixel")
      ->check(CLI::Range(1, 4096))
      ->capture_default_str();
  command->add_option("--seed", options->reference.seed, "Seed of the jitter")
      ->check(CLI::Range(std::int64_t{0}, std::int64_t{2147483647}))
      ->capture_default_str();
  command->add_option("--threads", options->reference.threads, "Worker threads (0: all cores)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  command->add_option("--aov", options->aov,
                      "Auxiliary channels to write, a comma list of depth (Z), normal (N.X N.Y N.Z), uv (U V); "
                      "docs/aov.md");
  add_set_option(*command, options->overrides, "the scene");
  add_resolution_options(*command, options->resolution);
  add_frame_option(*command, options->frame);
  add_output_options(*command, options->output);
  command->callback([&action, options] { action = [options] { return run_reference(*options); }; });
}

}  // namespace facet::cli
