// The per-frame error along a scene's camera path (`facet bench`, docs/report.md "Along the camera
// path"): each method's frames at evenly spaced frames of the path, each against a reference of its own
// frame, and how smoothly that error changes from frame to frame. A hand-over between methods that
// moved with the camera (a seam) would show as a jump above the content's own changes (issue 18).
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "report/method_catalogue.hpp"
#include "report/reference_cache.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

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

struct CameraPathRequest {
  ReferenceKey reference;  // the still camera's key; each frame's reference adds its frame number
  std::filesystem::path cache_dir;
  std::vector<int> frames;     // the frames of the path to measure (path_sample_frames)
  std::function<void()> tick;  // after each reference and each method's frame (may be empty)
};

// The references of the request's frames (cached like the still camera's), then each method's frames
// against them. A method that fails on a frame is left out of the result.
std::vector<CameraPathSeries> measure_camera_path(vk::Context& context, const Scene& scene,
                                                  std::span<const CatalogueEntry> methods,
                                                  const CameraPathRequest& request);

// The series as a line plot (report/line_plot.hpp, <svg class="camera-path">): RMSE against frame.
std::string camera_path_svg(std::span<const CameraPathSeries> series, const std::string& title);

}  // namespace facet::report
