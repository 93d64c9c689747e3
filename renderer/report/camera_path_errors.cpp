#include "report/camera_path_errors.hpp"

#include <cstdint>

#include "frames/prepared_frames.hpp"
#include "image/image_comparison.hpp"
#include "scene/camera_path.hpp"

namespace facet::report {

std::vector<CameraPathSeries> measure_camera_path(vk::Context& context, const Scene& scene,
                                                  std::span<const CatalogueEntry> methods,
                                                  const CameraPathRequest& request) {
  const std::vector<int>& frames = request.frames;
  const int width = request.reference.width, height = request.reference.height;
  frames::PreparedFrames reference_frames(
      scene, frames::ReferenceMethod{request.reference.grid, static_cast<std::int64_t>(request.reference.seed), 0},
      nullptr);
  std::vector<Image> references;
  for (int frame : frames) {
    ReferenceKey key = request.reference;
    key.frame = frame;
    references.push_back(cached_reference(request.cache_dir, key, [&] {
                           return reference_frames.render(camera_at(scene, frame), width, height).image;
                         }).image);
    if (request.tick) request.tick();
  }
  std::vector<CameraPathSeries> result;
  for (const CatalogueEntry& method : methods) {
    CameraPathSeries series{method.name, frames, {}, {}};
    try {
      frames::PreparedFrames prepared(scene, method.render_method(), &context);
      for (std::size_t i = 0; i < frames.size(); ++i) {
        const ImageComparison c =
            compare_images(prepared.render(camera_at(scene, frames[i]), width, height).image, references[i]);
        series.rmse.push_back(c.rmse);
        series.flip.push_back(c.flip);
        if (request.tick) request.tick();
      }
    } catch (const std::exception&) {
      continue;  // its still frame's record already carries the error
    }
    result.push_back(std::move(series));
  }
  return result;
}

}  // namespace facet::report
