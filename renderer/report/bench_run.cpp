#include "report/bench_run.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <set>

#include "common/error.hpp"
#include "common/progress.hpp"
#include "frames/prepared_frames.hpp"
#include "gpu/work_per_pixel.hpp"
#include "image/atomic_file.hpp"
#include "image/flip.hpp"
#include "image/heatmap.hpp"
#include "image/metrics.hpp"
#include "image/png_io.hpp"
#include "image/thumbnail.hpp"
#include "report/calibration_plot.hpp"
#include "report/camera_path_errors.hpp"
#include "report/method_catalogue.hpp"
#include "report/output_folder.hpp"
#include "report/reference_cache.hpp"
#include "report/run_info.hpp"
#include "report/svg_plot.hpp"
#include "scene/camera_path.hpp"
#include "scene/scene_loader.hpp"

namespace facet::report {

namespace {

constexpr int kQuickWidth = 160;
// Work is counted on a frame at most this wide (the bench's aspect): the count is per pixel.
constexpr int kWorkCountWidth = 160;
constexpr int kThumbnailWidth = 320;
// Frames sampled along a camera path by default: enough for the error's curve, each with its reference.
constexpr int kQuickPathFrames = 4, kPathFrames = 12;

// "ss:4" -> "ss-4": safe in file names and URLs.
std::string file_stem(const std::string& method) {
  std::string stem = method;
  for (char& c : stem)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.') c = c == ':' ? '-' : '_';
  return stem;
}

// Scene names (file stems), made unique with a numeric suffix.
std::string unique_name(const std::filesystem::path& file, std::set<std::string>& taken) {
  std::string name = file_stem(file.stem().string());
  for (int k = 2; !taken.insert(name).second; ++k) name = file_stem(file.stem().string()) + "_" + std::to_string(k);
  return name;
}

// Overrides first; a side not given follows the scene's aspect. Quick runs default to 160 px wide.
std::pair<int, int> resolution(const BenchOptions& options, const Camera& camera) {
  const bool quick_width = options.quick && options.width <= 0 && options.height <= 0;
  return frames::frame_size(camera, quick_width ? std::min(kQuickWidth, camera.width) : options.width, options.height);
}

// How well a method's per-pixel error estimate (docs/error_estimate.md) ranks and sizes its true error:
// one more frame with the `error` channel, untimed (its program accumulates the estimate, the timed
// one does not). Empty for methods without an estimate.
std::optional<ErrorEstimateQuality> judge_estimate(vk::Context& context, const Scene& scene,
                                                   const CatalogueEntry& method, const Image& reference) {
  gpu::RenderMethod estimating = method.render_method();
  if (!estimating.estimates_error()) return std::nullopt;
  estimating.aovs.error = true;
  frames::PreparedFrames prepared(scene, estimating, &context);
  const Image image = prepared.render(scene.camera, reference.width, reference.height).image;
  const auto channel = std::find_if(image.channels.begin(), image.channels.end(),
                                    [](const NamedChannel& c) { return c.name == "error"; });
  if (channel == image.channels.end()) return std::nullopt;
  return judge_covered_pixels(channel->values, absolute_error_map(image, reference).values, image.alpha);
}

// Times one method on one scene; any failure becomes the record's error.
BenchRecord measure_method(vk::Context& context, const Scene& scene, const CatalogueEntry& method,
                           const Image& reference, int repeats, const std::filesystem::path& out_dir,
                           const std::string& scene_name, const std::optional<gpu::PeakProbe>& probe,
                           BenchRecord record, const std::function<void()>& tick) {
  record.method = method.name;
  try {
    // Each method's set-up includes compiling its pipelines, as `facet render` pays it alone.
    context.pipelines().clear();
    const auto prepare_start = std::chrono::steady_clock::now();
    frames::PreparedFrames prepared(scene, method.render_method(), &context);
    const auto render = [&] { return prepared.render(scene.camera, reference.width, reference.height); };
    // The first frame is the warm-up and gives the image.
    record.phases = prepared.preparation();
    const frames::Frame first = timed(&record.phases, "first_frame", render);
    record.prepare_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - prepare_start).count();
    tick();
    record.timing = time_repeats(repeats, [&] {
      const double gpu_ms = render().gpu_ms;
      tick();
      return gpu_ms;
    });
    if (probe) {
      const int width = std::min(reference.width, kWorkCountWidth);
      const int height = std::max(1, static_cast<int>(std::lround(double(reference.height) * width / reference.width)));
      const gpu::WorkCount work = gpu::count_work(context, scene, method.render_method(), width, height);
      record.probe_fma_per_second = probe->fma_per_second;
      record.probe_texel_reads_per_second = probe->texel_reads_per_second;
      record.work_fma_per_pixel = work.fma_per_pixel;
      record.reads_per_pixel = work.reads_per_pixel;
    }
    record.comparison = compare_images(first.image, reference);
    record.error_estimate = judge_estimate(context, scene, method, reference);
    record.image = scene_name + "/" + file_stem(method.name) + ".png";
    record.heatmap = scene_name + "/" + file_stem(method.name) + ".flip.png";
    write_png_preview(out_dir / record.image, thumbnail(first.image, kThumbnailWidth));
    write_heatmap_png(out_dir / record.heatmap, thumbnail(flip_map(first.image, reference), kThumbnailWidth),
                      kHeatmapMaxFlip);
  } catch (const std::exception& e) {
    record.error = e.what();
    record.timing = {};
    record.error_estimate.reset();
    record.image.clear();
    record.heatmap.clear();
  }
  return record;
}

// The methods that ran along the scene's camera path: each record gets its series, the scene the plot.
void run_camera_path(vk::Context& context, const Scene& scene, std::span<const CatalogueEntry> methods,
                     CameraPathRequest request, SceneRun& run, BenchRun& bench, const std::filesystem::path& out_dir) {
  ProgressBar progress("camera path " + run.name,
                       static_cast<std::int64_t>(request.frames.size() * (1 + methods.size())));
  std::int64_t done = 0;
  request.tick = [&] { progress.update(++done); };
  const std::vector<CameraPathSeries> series = measure_camera_path(context, scene, methods, request);
  progress.finish();
  for (const CameraPathSeries& s : series)
    for (BenchRecord& record : bench.records)
      if (record.scene == run.name && record.method == s.method) record.path = s;
  run.path_plot = run.name + "/camera_path.svg";
  run.path_plot_svg = camera_path_svg(series, run.name + ": error along the camera path");
  write_file_atomically(out_dir / run.path_plot, run.path_plot_svg);
}

void run_scene(vk::Context& context, const BenchOptions& options, const std::filesystem::path& cache_dir, SceneRun& run,
               BenchRun& bench) {
  BenchRecord base;
  base.scene = run.name;
  base.scene_file = run.scene_file;
  base.device = bench.device;
  base.machine = bench.machine;
  base.facet_version = bench.facet_version;
  base.overrides = bench.overrides;
  Scene scene;
  CachedReference reference;
  ReferenceKey reference_key;
  try {
    scene = load_scene(run.scene_file, bench.overrides);
    std::tie(run.width, run.height) = resolution(options, scene.camera);
    std::unique_ptr<ProgressBar> bar;
    frames::PreparedFrames reference_frames(
        scene, frames::ReferenceMethod{bench.grid, static_cast<std::int64_t>(bench.seed), 0}, nullptr);
    frames::FrameRequest request;
    request.progress = [&](std::int64_t done, std::int64_t total) {
      if (!bar) bar = std::make_unique<ProgressBar>("reference " + run.name, total);
      bar->update(done);
    };
    reference_key = {.scene_file = run.scene_file,
                     .renderer_version = bench.facet_version,
                     .width = run.width,
                     .height = run.height,
                     .grid = bench.grid,
                     .seed = bench.seed,
                     .overrides = bench.overrides};
    reference = cached_reference(cache_dir, reference_key, [&] {
      return reference_frames.render(scene.camera, run.width, run.height, request).image;
    });
    if (bar) bar->finish();
    std::filesystem::create_directories(options.out_dir / run.name);
    run.reference_image = run.name + "/reference.png";
    write_png_preview(options.out_dir / run.reference_image, thumbnail(reference.image, kThumbnailWidth));
  } catch (const std::exception& e) {
    run.error = e.what();
    base.method = "reference";
    base.width = run.width;
    base.height = run.height;
    base.error = run.error;
    bench.records.push_back(base);
    return;
  }
  run.reference_key = reference.key;
  run.reference_cache_hit = reference.cache_hit;
  run.reference_ms = reference.render_ms;
  base.width = run.width;
  base.height = run.height;

  const std::vector<CatalogueEntry> methods = select_methods(scene_features(scene), options.quick, options.methods);
  ProgressBar progress("bench " + run.name, static_cast<std::int64_t>(methods.size()) * (bench.repeats + 1));
  std::int64_t step = 0;
  std::vector<PlotPoint> points, wall_points;
  std::vector<CalibrationCurve> calibration;
  std::vector<CatalogueEntry> ran;
  for (std::size_t i = 0; i < methods.size(); ++i) {
    BenchRecord record = measure_method(context, scene, methods[i], reference.image, bench.repeats, options.out_dir,
                                        run.name, bench.probe, base, [&] { progress.update(++step); });
    step = static_cast<std::int64_t>(i + 1) * (bench.repeats + 1);  // a failed method skips its remaining runs
    progress.update(step);
    if (record.ok()) {
      points.push_back({record.method, record.time_ms(), record.comparison.rmse});
      wall_points.push_back({record.method, record.timing.wall_ms.median, record.comparison.rmse});
      if (record.error_estimate) calibration.push_back({record.method, record.error_estimate->calibration});
      ran.push_back(methods[i]);
    }
    bench.records.push_back(std::move(record));
  }
  progress.finish();
  run.plot = run.name + "/speed_error.svg";
  run.plot_svg =
      speed_error_svg(points, {run.name + ": speed vs error", "time per frame (ms, median)", "RMSE vs reference"});
  write_file_atomically(options.out_dir / run.plot, run.plot_svg);
  run.wall_plot = run.name + "/wall_error.svg";
  run.wall_plot_svg = speed_error_svg(
      wall_points, {run.name + ": wall time vs error", "wall time per frame (ms, median)", "RMSE vs reference"});
  write_file_atomically(options.out_dir / run.wall_plot, run.wall_plot_svg);
  if (!calibration.empty()) {
    run.calibration_plot = run.name + "/calibration.svg";
    run.calibration_plot_svg = calibration_svg(calibration, run.name + ": error estimate calibration");
    write_file_atomically(options.out_dir / run.calibration_plot, run.calibration_plot_svg);
  }
  const int path_frames = options.path_frames >= 0 ? options.path_frames
                          : options.quick          ? kQuickPathFrames
                                                   : kPathFrames;
  if (scene.camera_path && path_frames > 0)
    run_camera_path(context, scene, ran,
                    {reference_key, cache_dir, path_sample_frames(frame_count(scene), path_frames), {}}, run, bench,
                    options.out_dir);
}

}  // namespace

int BenchRun::exit_status() const {
  const bool scene_failed =
      std::any_of(scenes.begin(), scenes.end(), [](const SceneRun& s) { return s.error.has_value(); });
  const bool any_ok = std::any_of(records.begin(), records.end(), [](const BenchRecord& r) { return r.ok(); });
  return scene_failed || !any_ok ? 1 : 0;
}

BenchRun run_bench(const BenchOptions& options) {
  if (options.scenes.empty()) throw Error("no scene given");
  std::set<std::string> taken;
  std::vector<std::string> names;
  for (const auto& file : options.scenes) names.push_back(unique_name(file, taken));
  prepare_output_folder(options.out_dir, names);
  std::error_code error;
  std::filesystem::create_directories(options.out_dir, error);
  if (error) throw Error(options.out_dir.string() + ": cannot create the output directory: " + error.message());

  BenchRun bench;
  bench.machine = machine_description();
  bench.facet_version = options.facet_version;
  bench.date = utc_timestamp();
  bench.quick = options.quick;
  bench.grid = options.grid > 0 ? options.grid : options.quick ? 8 : 32;
  bench.repeats = options.repeats > 0 ? options.repeats : options.quick ? 2 : 5;
  bench.seed = options.seed;
  bench.overrides = options.overrides;
  vk::Context context(options.device);
  bench.device = context.info().name;
  if (options.roofline) bench.probe = gpu::probe_peak(context);
  const std::filesystem::path cache_dir = options.cache_dir.empty() ? options.out_dir / "cache" : options.cache_dir;

  for (std::size_t i = 0; i < options.scenes.size(); ++i) {
    SceneRun run;
    run.name = names[i];
    run.scene_file = options.scenes[i].string();
    run_scene(context, options, cache_dir, run, bench);
    bench.scenes.push_back(run);
  }
  if (options.kernel_stability) bench.stability = kernel_stability(context);
  return bench;
}

}  // namespace facet::report
