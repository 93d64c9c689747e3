// One line of results.json: a method/setting timed and measured on one scene, or its error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/phase_timings.hpp"
#include "image/error_estimate_quality.hpp"
#include "image/image_comparison.hpp"
#include "report/camera_path_series.hpp"
#include "report/timing.hpp"

namespace facet::report {

struct BenchRecord {
  std::string scene;  // short name (the file's stem), also the scene's output folder
  std::string scene_file;
  std::string method;
  int width = 0, height = 0;
  std::string device, machine, facet_version;
  std::vector<std::string> overrides;  // --set of the scene, as given
  std::optional<std::string> error;    // set: the method failed; no timing, metrics or images
  Timing timing;
  double prepare_ms = 0.0;  // wall time of preparing the method and rendering its first (warm-up) frame
  PhaseTimings phases;      // of that: the preparation's phases and first_frame
  ImageComparison comparison;
  std::string image, heatmap;                          // PNG paths relative to the output folder
  std::optional<ErrorEstimateQuality> error_estimate;  // methods that estimate their per-pixel error (filtered...)
  // The roofline (docs/report.md): the host's measured peak (gpu/peak_probe.hpp) and the method's work
  // per pixel, counted by its instrumented render pass (gpu/work_per_pixel.hpp); unset: not measured.
  std::optional<double> probe_fma_per_second, probe_texel_reads_per_second;
  std::optional<double> work_fma_per_pixel, reads_per_pixel;
  std::optional<CameraPathSeries> path;  // along the scene's camera path (report/camera_path_series.hpp)

  bool ok() const { return !error.has_value(); }
  double time_ms() const { return timing.headline().median; }
  // width x height x work / peak: the device time of a frame that ran at the host's FMA peak; of its texel
  // fetches at the host's fetch peak.
  std::optional<double> roofline_fma_ms() const;
  std::optional<double> roofline_reads_ms() const;
  // The larger of the two (either where the other is not measured): the time below which no frame of this
  // work can run on this host.
  std::optional<double> roofline_ms() const;
  // Median device time / roofline_ms: how many times slower than the limit.
  std::optional<double> device_vs_roofline() const;
};

// Keys: scene, scene_file, set (the --set overrides, [] if none), method, width, height, device, machine,
// facet_version and either
// error, or time_ms (median; device time when there is one, else wall), time_ms_min, time_ms_max,
// time_source ("gpu" | "wall"), wall_ms (median), wall_ms_min, wall_ms_max, gpu_ms (median or null),
// repeats, prepare_ms, phases ({name: wall ms}), the metrics of facet compare (rmse, rel_mse, psnr, max_abs, ssim,
// flip), image, heatmap, probe_fma_per_second, probe_texel_reads_per_second, work_fma_per_pixel, reads_per_pixel,
// roofline_fma_ms, roofline_reads_ms, roofline_ms and device_vs_roofline (each null when not measured: `facet bench
// --no-roofline`, or no device time); for a method that estimates its error, also error_spearman, error_mean_ratio,
// error_calibration (as facet compare); on a scene with a camera path, path: {frames, rmse, flip (one per sampled
// frame), rmse_jump_ratio, flip_jump_ratio}. results.json adds `schema` to each (report_files.hpp).
nlohmann::json to_json(const BenchRecord& record);

// A number, or null when unset: the optional figures of results.json and run.json.
nlohmann::json number_or_null(const std::optional<double>& value);

}  // namespace facet::report
