#include "cli/frame_output.hpp"

#include "cli/output_extension.hpp"
#include "frames/prepared_frames.hpp"
#include "scene/camera_path.hpp"

namespace facet::cli {

namespace {
constexpr int kMaxResolution = 16384;  // the scene format's bound on each side
}

std::pair<int, int> ResolutionOptions::resolve(const Camera& camera) const {
  return frames::frame_size(camera, width, height);
}

void add_resolution_options(CLI::App& command, ResolutionOptions& options) {
  command
      .add_option("--width", options.width, "Image width in pixels (default: the scene's, or --height at its aspect)")
      ->check(CLI::Range(1, kMaxResolution));
  command
      .add_option("--height", options.height, "Image height in pixels (default: the scene's, or --width at its aspect)")
      ->check(CLI::Range(1, kMaxResolution));
}

void FrameOption::apply(Scene& scene) const {
  if (frame >= 0) scene.camera = camera_at(scene, frame);
}

void add_frame_option(CLI::App& command, FrameOption& option) {
  command.add_option("--frame", option.frame, "Render frame F of the scene's camera_path (default: its still camera)")
      ->check(CLI::Range(0, kMaxPathFrames - 1));
}

void add_output_options(CLI::App& command, frames::FrameFile& options) {
  command.add_option("-o,--output", options.path, "Output OpenEXR file (scene-linear RGB)")
      ->required()
      ->check(output_extension(".exr", "OpenEXR"));
  command.add_option("--pixel-type", options.pixel_type, "EXR channel type")
      ->check(CLI::IsMember({"half", "float"}))
      ->capture_default_str();
  command.add_option("--exposure", options.exposure, "Exposure of the PNG preview, in stops")->capture_default_str();
  command.add_flag("!--no-preview", options.preview, "Do not write the sRGB PNG preview beside the EXR");
}

}  // namespace facet::cli
