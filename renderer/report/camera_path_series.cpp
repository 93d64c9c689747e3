#include "report/camera_path_series.hpp"

#include <algorithm>
#include <cmath>

#include "report/line_plot.hpp"

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
