// The options every rendering subcommand shares: resolution overrides, the camera_path frame, and
// where and how the frame is written (frames/frame_file.hpp).
#pragma once

#include <utility>

#include <CLI/CLI.hpp>

#include "frames/frame_file.hpp"
#include "scene/scene.hpp"

namespace facet::cli {

struct ResolutionOptions {
  int width = 0;  // 0: the scene's own
  int height = 0;
  // The image size to render: the overrides where given, else the scene camera's.
  std::pair<int, int> resolve(const Camera& camera) const;
};
void add_resolution_options(CLI::App& command, ResolutionOptions& options);

// --frame F: frame F of the scene's camera_path (scene/camera_path.hpp) instead of its still camera.
struct FrameOption {
  int frame = -1;  // -1: the still `camera`
  // Puts the frame's camera into `scene`; nothing for -1.
  void apply(Scene& scene) const;
};
void add_frame_option(CLI::App& command, FrameOption& option);

void add_output_options(CLI::App& command, frames::FrameFile& options);

}  // namespace facet::cli
