// The per-frame error along a scene's camera path as data (`facet bench`, docs/report.md "Along the
// camera path"): each method's errors at evenly spaced frames of the path, how smoothly they change from
// frame to frame, and their plot. A hand-over between methods that moved with the camera (a seam) would
// show as a jump above the content's own changes (issue 18). report/camera_path_errors.hpp measures them.
#pragma once

#include <span>
#include <string>
#include <vector>

namespace facet::report {

// One method's errors at the sampled frames.
struct CameraPathSeries {
  std::string method;
  std::vector<int> frames;
  std::vector<double> rmse, flip;
};

// The frames to sample from a path of `count` frames: `samples` of them (at most `count`) evenly
// spaced, the first and the last included.
std::vector<int> path_sample_frames(int count, int samples);

// How a sequence of per-frame errors changes between consecutive samples: the mean and the largest
// absolute change. jump_ratio = largest / mean (0 for a constant or single-sample sequence): 1 when
// every change is as large, higher where one change stands out.
struct ErrorSmoothness {
  double mean_change = 0.0, largest_change = 0.0;
  double jump_ratio() const { return mean_change > 0.0 ? largest_change / mean_change : 0.0; }
};
ErrorSmoothness error_smoothness(std::span<const double> errors);

// The series as a line plot (report/line_plot.hpp, <svg class="camera-path">): RMSE against frame.
std::string camera_path_svg(std::span<const CameraPathSeries> series, const std::string& title);

}  // namespace facet::report
