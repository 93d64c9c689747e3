// Measures the per-frame error along a scene's camera path (`facet bench`, docs/report.md "Along the
// camera path"): each method's frames at the sampled frames of the path, each against a reference of
// its own frame (report/camera_path_series.hpp holds the result and what is derived from it).
#pragma once

#include <filesystem>
#include <functional>
#include <span>
#include <vector>

#include "report/camera_path_series.hpp"
#include "report/method_catalogue.hpp"
#include "report/reference_cache.hpp"
#include "scene/scene.hpp"
#include "vk/context.hpp"

namespace facet::report {

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

}  // namespace facet::report
