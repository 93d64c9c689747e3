#include "report/camera_path_errors.hpp"

#include <algorithm>
#include <cmath>

#include "frames/prepared_frames.hpp"
#include "image/image_comparison.hpp"
#include "report/line_plot.hpp"
#include "scene/camera_path.hpp"

namespace facet::report {

std::vector<int> path_sample_frames(int count, int samples) {
  samples = std::clamp(samples, 0, count);
  if (samples == 1) return {0};
  std::vector<int> frames;
  for (int i = 0; i < samples; ++i) {
    const int frame = static_cast<int>(std::lround(static_cast<double>(i) * (count - 1) / (samples - 1)));
    if (frames.empty() || frame != frames.back()) frames.push_back(frame);
  }
  return frames;
}

ErrorSmoothness error_smoothness(std::span<const double> errors) {
  ErrorSmoothness s;
  if (errors.size() < 2) return s;
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double change = std::abs(errors[i] - errors[i - 1]);
    s.mean_change += change;
    s.largest_change = std::max(s.largest_change, change);
  }
  s.mean_change /= static_cast<double>(errors.size() - 1);
  return s;
}

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

std::string camera_path_svg(std::span<const CameraPathSeries> series, const std::string& title) {
  std::vector<LineCurve> curves;
  for (const CameraPathSeries& s : series) {
    LineCurve curve{s.method, {}};
    for (std::size_t i = 0; i < s.frames.size(); ++i) curve.points.emplace_back(s.frames[i], s.rmse[i]);
    curves.push_back(std::move(curve));
  }
  const double first = series.empty() || series.front().frames.empty() ? 0.0 : series.front().frames.front();
  return line_plot_svg(curves, {.svg_class = "camera-path",
                                .point_noun = "RMSE",
                                .x_noun = "frame",
                                .title = title,
                                .x_axis = "frame of the camera path",
                                .y_axis = "RMSE vs that frame's reference",
                                .plot_width = 420.0,
                                .plot_height = 200.0,
                                .x_lo = first});
}

}  // namespace facet::report
