#include "cli/frame_output.hpp"

#include "common/error.hpp"
#include "image/png_io.hpp"
#include "scene/camera_path.hpp"

namespace facet::cli {

namespace {
constexpr int kMaxResolution = 16384;  // the scene format's bound on each side
}

std::pair<int, int> ResolutionOptions::resolve(const Camera& camera) const {
  return {width > 0 ? width : camera.width, height > 0 ? height : camera.height};
}

void add_resolution_options(CLI::App& command, ResolutionOptions& options) {
  command.add_option("--width", options.width, "Image width in pixels (default: the scene's)")
      ->check(CLI::Range(1, kMaxResolution));
  command.add_option("--height", options.height, "Image height in pixels (default: the scene's)")
      ->check(CLI::Range(1, kMaxResolution));
}

void FrameOption::apply(Scene& scene) const {
  if (frame >= 0) scene.camera = camera_at(scene, frame);
}

void FrameOption::annotate(ExrMetadata& metadata) const {
  if (frame >= 0) metadata["facet:frame"] = static_cast<std::int64_t>(frame);
}

void add_frame_option(CLI::App& command, FrameOption& option) {
  command.add_option("--frame", option.frame, "Render frame F of the scene's camera_path (default: its still camera)")
      ->check(CLI::Range(0, kMaxPathFrames - 1));
}

void add_output_options(CLI::App& command, OutputOptions& options) {
  command.add_option("-o,--output", options.path, "Output OpenEXR file (scene-linear RGB)")->required();
  command.add_option("--pixel-type", options.pixel_type, "EXR channel type")
      ->check(CLI::IsMember({"half", "float"}))
      ->capture_default_str();
  command.add_option("--exposure", options.exposure, "Exposure of the PNG preview, in stops")
      ->capture_default_str();
  command.add_flag("!--no-preview", options.preview, "Do not write the sRGB PNG preview beside the EXR");
}

ExrMetadata frame_metadata(const Scene& scene, const std::string& method, int64_t samples_per_pixel,
                           const std::string& device, double gpu_ms, double wall_ms) {
  return {{"facet:scene", scene.source.string()},
          {"facet:method", method},
          {"facet:spp", samples_per_pixel},
          {"facet:gpu_ms", gpu_ms},
          {"facet:render_ms", wall_ms},
          {"facet:device", device},
          {"facet:version", std::string(FACET_VERSION)}};
}

void add_reference_metadata(ExrMetadata& metadata, int grid, std::int64_t seed) {
  metadata["facet:grid"] = static_cast<std::int64_t>(grid);
  metadata["facet:seed"] = seed;
  metadata["facet:filter"] = std::string("box");
}

void write_frame(const OutputOptions& options, const Image& image, const ExrMetadata& metadata) {
  if (options.path.extension() != ".exr")
    throw Error(options.path.string() + ": the output must be an .exr file");
  std::error_code error;
  if (options.path.has_parent_path()) std::filesystem::create_directories(options.path.parent_path(), error);
  if (error)
    throw Error(options.path.parent_path().string() + ": cannot create the output directory: " + error.message());
  write_exr(options.path, image, metadata,
            options.pixel_type == "float" ? ExrPixelType::Float : ExrPixelType::Half);
  if (options.preview) write_png_preview(std::filesystem::path(options.path).replace_extension(".png"), image,
                                         options.exposure);
}

}  // namespace facet::cli
