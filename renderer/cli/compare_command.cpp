// facet compare A.exr B.exr: error metrics of A against the reference B, an error heat map, and
// thresholds that make it a CI gate.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "cli/compare_gate.hpp"
#include "cli/output_extension.hpp"
#include "image/crop.hpp"
#include "image/flip.hpp"
#include "image/heatmap.hpp"
#include "image/image_comparison.hpp"
#include "image/image_file.hpp"
#include "image/metrics.hpp"

namespace facet::cli {

namespace {

struct CompareOptions {
  std::filesystem::path test;
  std::filesystem::path reference;
  std::filesystem::path heatmap;
  std::string heatmap_metric = "flip";
  double heatmap_max = 0.0;  // 0: 1 for FLIP, else the map's maximum
  bool json = false;
  std::vector<std::string> fail;  // METRIC>VALUE or METRIC<VALUE
  std::vector<int> crop;          // x, y, width, height; empty: the whole images
};

// The image, or its --crop region.
Image read_region(const std::filesystem::path& path, const std::vector<int>& region) {
  Image image = read_image(path);
  return region.empty() ? image : crop(image, {region[0], region[1], region[2], region[3]});
}

int run_compare(const CompareOptions& options) {
  std::vector<Threshold> thresholds;
  for (const std::string& spec : options.fail) thresholds.push_back(parse_threshold(spec));
  Image test = read_region(options.test, options.crop);
  Image reference = read_region(options.reference, options.crop);
  const ImageComparison comparison = compare_images(test, reference);
  nlohmann::json result = to_json(comparison);
  result["width"] = test.width;
  result["height"] = test.height;
  if (!options.heatmap.empty()) {
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
  const std::string failed = failed_thresholds(comparison, thresholds);
  if (!failed.empty()) std::cerr << "facet: compare: failed: " << failed << "\n";
  const int status = failed.empty() ? 0 : 1;
  if (options.json) {
    std::cout << result.dump() << "\n";
    return status;
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
  return status;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("compare", "Error metrics of an image against a reference");
  auto options = std::make_shared<CompareOptions>();
  command->add_option("test", options->test, "The image to judge (EXR, or an sRGB PNG read as linear)")->required();
  command->add_option("reference", options->reference, "The reference image (EXR or PNG)")->required();
  command->add_option("--heatmap", options->heatmap, "Write a false-colour error map (PNG)")
      ->check(output_extension(".png", "PNG"));
  command->add_option("--heatmap-metric", options->heatmap_metric, "Per-pixel error shown in the heat map")
      ->check(CLI::IsMember({"flip", "abs", "rel"}))
      ->capture_default_str();
  command
      ->add_option("--heatmap-max", options->heatmap_max,
                   "Error shown at full scale (default: 1 for FLIP, else the map's maximum)")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--json", options->json,
                    "Print one JSON object: rmse, rel_mse, psnr (null if identical), max_abs, ssim, flip");
  command
      ->add_option("--fail", options->fail,
                   "METRIC>VALUE or METRIC<VALUE (repeatable): exit 1 if a metric crosses it, e.g. rmse>0.01, "
                   "psnr<30")
      ->allow_extra_args(false);
  command->add_option("--crop", options->crop, "x,y,w,h: compare only this region of both images")
      ->delimiter(',')
      ->expected(4);
  command->callback([&action, options] { action = [options] { return run_compare(*options); }; });
}

}  // namespace facet::cli
