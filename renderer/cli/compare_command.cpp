// facet compare A.exr B.exr: error metrics of A against the reference B, an error heat map, and
// thresholds that make it a CI gate. With --sheet, several tests against one reference, drawn side by
// side with their errors and heat maps in one PNG.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/compare_gate.hpp"
#include "cli/output_extension.hpp"
#include "common/error.hpp"
#include "image/compare_sheet.hpp"
#include "image/crop.hpp"
#include "image/error_estimate_quality.hpp"
#include "image/exr_io.hpp"
#include "image/flip.hpp"
#include "image/heatmap.hpp"
#include "image/image_comparison.hpp"
#include "image/image_file.hpp"
#include "image/metrics.hpp"
#include "image/png_io.hpp"
#include "image/stored_precision.hpp"

namespace facet::cli {

namespace {

struct CompareOptions {
  std::vector<std::filesystem::path> images;  // TEST REFERENCE, or with --sheet TEST... REFERENCE
  std::filesystem::path sheet;
  std::filesystem::path heatmap;
  std::string heatmap_metric = "flip";
  double heatmap_max = 0.0;  // 0: 1 for FLIP, else the map's maximum
  bool json = false;
  std::vector<std::string> fail;  // METRIC>VALUE or METRIC<VALUE
  std::vector<int> crop;          // x, y, width, height; empty: the whole images
};

// The image, or its --crop region, with its metadata (the sheet's labels).
SheetImage read_region(const std::filesystem::path& path, const std::vector<int>& region) {
  SheetImage read;
  read.image = read_image(path, &read.metadata);
  if (!region.empty()) read.image = crop(read.image, {region[0], region[1], region[2], region[3]});
  read.stem = path.stem().string();
  return read;
}

// Writes the --heatmap PNG and records its name and scale in `result`.
void write_heatmap(const CompareOptions& options, const Image& test, const Image& reference, nlohmann::json& result) {
  ScalarImage map = options.heatmap_metric == "flip"  ? flip_map(test, reference)
                    : options.heatmap_metric == "abs" ? absolute_error_map(test, reference)
                                                      : relative_error_map(test, reference);
  double max_value = options.heatmap_max;
  if (max_value <= 0.0) {
    max_value = options.heatmap_metric == "flip" ? 1.0 : *std::max_element(map.values.begin(), map.values.end());
    if (!(max_value > 0.0)) max_value = 1.0;  // identical images: an all-black map
  }
  write_heatmap_png(options.heatmap, map, max_value);
  result["heatmap"] = options.heatmap.string();
  result["heatmap_max"] = max_value;
}

// A frame with an `error` channel (`--aov error`): how its estimate ranks and sizes the true per-pixel
// error (the mean absolute error over R, G, B, at the resolution both files store: resolved_error_map) over
// the pixels its A channel marks as covered (all pixels without A), within --crop if given;
// docs/error_estimate.md.
void add_error_estimate_quality(const std::filesystem::path& path, const std::filesystem::path& reference_path,
                                const std::vector<int>& region, const Image& test, const Image& reference,
                                nlohmann::json& result) {
  if (path.extension() != ".exr" || !exr_has_channel(path, "error")) return;
  ScalarImage estimate = read_exr_scalar(path, "error");
  ScalarImage coverage = exr_has_channel(path, "A") ? read_exr_scalar(path, "A") : ScalarImage(estimate.width, estimate.height, 1.0f);
  if (!region.empty()) {
    const PixelRect rect{region[0], region[1], region[2], region[3]};
    estimate = crop(estimate, rect);
    coverage = crop(coverage, rect);
  }
  const std::optional<ErrorEstimateQuality> quality = judge_covered_pixels(
      estimate.values,
      resolved_error_map(test, reference, stored_precision(path), stored_precision(reference_path)).values,
      coverage.values);
  if (quality) result.update(to_json(*quality));
}

void print_result(const nlohmann::json& result, bool json) {
  if (json) {
    std::cout << result.dump() << "\n";
    return;
  }
  auto text = [&](const char* key, const char* if_null) {
    return result[key].is_null() ? std::string(if_null) : result[key].dump();
  };
  std::cout << "rmse     " << text("rmse", "") << "\n"
            << "rel_mse  " << text("rel_mse", "") << "\n"
            << "psnr     " << text("psnr", "inf (identical)") << " dB\n"
            << "max_abs  " << text("max_abs", "") << "\n"
            << "ssim     " << text("ssim", "undefined (smaller than 11x11)") << "\n"
            << "flip     " << text("flip", "") << "\n";
  if (result.contains("error_spearman"))
    std::cout << "error estimate: spearman " << result["error_spearman"].dump() << ", mean ratio "
              << result["error_mean_ratio"].dump() << "\n";
}

int run_compare(const CompareOptions& options) {
  const bool sheet = !options.sheet.empty();
  if (options.images.size() < 2 || (!sheet && options.images.size() > 2))
    throw Error("compare takes TEST REFERENCE, or TEST... REFERENCE with --sheet SHEET.png; got " +
                std::to_string(options.images.size()) + (options.images.size() == 1 ? " image" : " images"));
  std::vector<Threshold> thresholds;
  for (const std::string& spec : options.fail) thresholds.push_back(parse_threshold(spec));
  std::vector<SheetImage> tests;
  for (auto path = options.images.begin(); path + 1 != options.images.end(); ++path)
    tests.push_back(read_region(*path, options.crop));
  const SheetImage reference = read_region(options.images.back(), options.crop);
  std::vector<ImageComparison> comparisons;
  for (const SheetImage& test : tests) comparisons.push_back(compare_images(test.image, reference.image));
  if (sheet) {
    const Rgb8Image picture = compare_sheet(tests, comparisons, reference);
    write_png_rgb8(options.sheet, picture.width, picture.height, picture.bytes);
  }

  // Each test's output is what `facet compare TEST REFERENCE` prints for it.
  int status = 0;
  for (std::size_t i = 0; i < tests.size(); ++i) {
    nlohmann::json result = to_json(comparisons[i]);
    result["width"] = tests[i].image.width;
    result["height"] = tests[i].image.height;
    if (!options.heatmap.empty()) write_heatmap(options, tests[i].image, reference.image, result);
    add_error_estimate_quality(options.images[i], options.images.back(), options.crop, tests[i].image, reference.image,
                               result);
    const std::string failed = failed_thresholds(comparisons[i], thresholds);
    if (!failed.empty()) {
      std::cerr << "facet: compare: failed: " << (sheet ? options.images[i].string() + ": " : "") << failed << "\n";
      status = 1;
    }
    print_result(result, options.json);
  }
  return status;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("compare", "Error metrics of an image against a reference");
  auto options = std::make_shared<CompareOptions>();
  command
      ->add_option("images", options->images,
                   "TEST REFERENCE: the image to judge, then the reference (EXR, or an sRGB PNG read as linear); "
                   "with --sheet, one or more tests, then the reference")
      ->required();
  auto* sheet = command
                    ->add_option("--sheet", options->sheet,
                                 "Write a PNG of the tests and the reference side by side, labelled with method, "
                                 "time and error, with each test's FLIP heat map")
                    ->check(output_extension(".png", "PNG"));
  command->add_option("--heatmap", options->heatmap, "Write a false-colour error map (PNG)")
      ->check(output_extension(".png", "PNG"))
      ->excludes(sheet);
  command->add_option("--heatmap-metric", options->heatmap_metric, "Per-pixel error shown in the heat map")
      ->check(CLI::IsMember({"flip", "abs", "rel"}))
      ->capture_default_str();
  command
      ->add_option("--heatmap-max", options->heatmap_max,
                   "Error shown at full scale (default: 1 for FLIP, else the map's maximum)")
      ->check(CLI::NonNegativeNumber);
  command->add_flag(
      "--json", options->json,
      "Print one JSON object (a line per test): rmse, rel_mse, psnr (null if identical), max_abs, ssim, flip");
  command
      ->add_option("--fail", options->fail,
                   "METRIC>VALUE or METRIC<VALUE (repeatable): exit 1 if a metric crosses it, e.g. rmse>0.01, "
                   "psnr<30")
      ->allow_extra_args(false);
  command->add_option("--crop", options->crop, "x,y,w,h: compare only this region of every image")
      ->delimiter(',')
      ->expected(4);
  command->callback([&action, options] { action = [options] { return run_compare(*options); }; });
}

}  // namespace facet::cli
