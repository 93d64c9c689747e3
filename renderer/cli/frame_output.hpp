// What every rendering subcommand shares: resolution overrides, where and how the frame is
// written (EXR + PNG preview), and the metadata every facet EXR carries.
#pragma once

#include <filesystem>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "image/exr_io.hpp"
#include "image/image.hpp"
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
  // Puts the frame's camera into `scene` and names the frame in `metadata`; nothing for -1.
  void apply(Scene& scene) const;
  void annotate(ExrMetadata& metadata) const;
};
void add_frame_option(CLI::App& command, FrameOption& option);

struct OutputOptions {
  std::filesystem::path path;
  std::string pixel_type = "half";
  double exposure = 0.0;
  bool preview = true;
};
void add_output_options(CLI::App& command, OutputOptions& options);

ExrMetadata frame_metadata(const Scene& scene, const std::string& method, int64_t samples_per_pixel,
                           const std::string& device, double gpu_ms, double wall_ms);

// The reference renderer's settings, for its frames' metadata.
void add_reference_metadata(ExrMetadata& metadata, int grid, std::int64_t seed);

// Writes the EXR (atomically) and, unless disabled, a PNG preview beside it (same stem).
void write_frame(const OutputOptions& options, const Image& image, const ExrMetadata& metadata);

}  // namespace facet::cli
