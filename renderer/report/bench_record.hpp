// One line of results.json: a method/setting timed and measured on one scene, or its error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/phase_timings.hpp"
#include "image/error_estimate_quality.hpp"
#include "image/image_comparison.hpp"
#include "report/timing.hpp"

namespace facet::report {

struct BenchRecord {
  std::string scene;  // short name (the file's stem), also the scene's output folder
  std::string scene_file;
  std::string method;
  int width = 0, height = 0;
  std::string device, machine, facet_version;
  std::vector<std::string> overrides;  // --set of the scene, as given
  std::optional<std::string> error;  // set: the method failed; no timing, metrics or images
  Timing timing;
  double prepare_ms = 0.0;  // wall time of preparing the method and rendering its first (warm-up) frame
  PhaseTimings phases;      // of that: the preparation's phases and first_frame
  ImageComparison comparison;
  std::string image, heatmap;  // PNG paths relative to the output folder
  std::optional<ErrorEstimateQuality> error_estimate;  // methods that estimate their per-pixel error (filtered...)

  bool ok() const { return !error.has_value(); }
  double time_ms() const { return timing.headline().median; }
};

// Keys: scene, scene_file, set (the --set overrides, [] if none), method, width, height, device, machine,
// facet_version and either
// error, or time_ms (median; device time when there is one, else wall), time_ms_min, time_ms_max,
// time_source ("gpu" | "wall"), wall_ms (median), wall_ms_min, wall_ms_max, gpu_ms (median or null),
// repeats, prepare_ms, phases ({name: wall ms}), the metrics of facet compare (rmse, rel_mse, psnr, max_abs, ssim, flip), image, heatmap;
// for a method that estimates its error, also error_spearman, error_mean_ratio, error_calibration (as facet compare).
// results.json adds `schema` to each (report_files.hpp).
nlohmann::json to_json(const BenchRecord& record);

}  // namespace facet::report
