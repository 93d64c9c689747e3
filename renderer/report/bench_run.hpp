// `facet bench`: per scene the reference (cached), then every applicable method timed over
// repeats and measured against it; thumbnails, heat maps and a speed-vs-error plot per scene.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "gpu/peak_probe.hpp"
#include "report/bench_record.hpp"
#include "report/kernel_stability.hpp"
#include "vk/context.hpp"

namespace facet::report {

// The FLIP value the heat maps' top colour stands for (index.html's colour bar shows the scale).
constexpr double kHeatmapMaxFlip = 1.0;

struct BenchOptions {
  std::vector<std::filesystem::path> scenes;
  std::filesystem::path out_dir;
  std::filesystem::path cache_dir;  // empty: out_dir/cache
  bool quick = false;               // small images, grid 8, ss:K up to 8, 2 repeats
  int width = 0, height = 0;        // 0: the mode's (quick: 160 px wide at the scene's aspect; else the scene's)
  int grid = 0;                     // reference N x N; 0: 8 quick, 32 full
  int repeats = 0;                  // timed runs per method; 0: 2 quick, 5 full
  std::uint64_t seed = 1;
  std::vector<std::string> methods;    // empty: the catalogue's applicable ones
  std::vector<std::string> overrides;  // --set PATH=VALUE, applied to every scene
  bool kernel_stability = true;
  bool roofline = true;  // probe the host's peak and count each method's work per pixel
  int path_frames = -1;  // frames sampled along a scene's camera path; -1: the mode's (4 quick, 12 full); 0: none
  std::string facet_version;
  vk::ContextOptions device;
};

struct SceneRun {
  std::string name, scene_file;
  int width = 0, height = 0;
  std::optional<std::string> error;  // the scene or its reference failed; no method ran
  std::string reference_key;
  bool reference_cache_hit = false;
  double reference_ms = 0.0;
  std::string reference_image, plot, wall_plot;  // relative to out_dir; plot: x = time_ms, wall_plot: x = wall_ms
  std::string plot_svg, wall_plot_svg;           // their text, for index.html to inline
  // The error estimates' calibration plot ("" when no method of the scene estimates its error).
  std::string calibration_plot, calibration_plot_svg;
  // The methods' per-frame error along the scene's camera path ("" without a path or with --path-frames 0).
  std::string path_plot, path_plot_svg;
};

struct BenchRun {
  std::string machine, device, facet_version, date;
  bool quick = false;
  int grid = 0, repeats = 0;
  std::uint64_t seed = 1;
  std::vector<std::string> overrides;   // --set, as given
  std::optional<gpu::PeakProbe> probe;  // the host's peak, measured once per run (unset: --no-roofline)
  std::vector<SceneRun> scenes;
  std::vector<BenchRecord> records;
  std::vector<StabilityRow> stability;
  // 0 when every scene's reference was made and at least one method ran; else 1 (method errors
  // alone are reported in the records and do not fail the run).
  int exit_status() const;
};

// Renders, measures and writes the images and plots under options.out_dir; the caller writes the
// reports (report_files.hpp). Throws facet::Error only for problems of the whole run (no device,
// an output folder that cannot be made).
BenchRun run_bench(const BenchOptions& options);

}  // namespace facet::report
