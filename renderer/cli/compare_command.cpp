// facet compare A.exr B.exr: error metrics of A against the reference B, and an error heat map.
#include <filesystem>
#include <algorithm>
#include <iostream>
#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "image/exr_io.hpp"
#include "image/flip.hpp"
#include "image/image_comparison.hpp"
#include "image/heatmap.hpp"
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
};

int run_compare(const CompareOptions& options) {
  Image test = read_exr(options.test);
  Image reference = read_exr(options.reference);
  nlohmann::json result = to_json(compare_images(test, reference));
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
  if (options.json) {
    std::cout << result.dump() << "\n";
    return 0;
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
  return 0;
}

}  // namespace

void add_compare_command(CLI::App& app, Action& action) {
  auto* command = app.add_subcommand("compare", "Error metrics of an image against a reference");
  auto options = std::make_shared<CompareOptions>();
  command->add_option("test", options->test, "The image to judge (EXR)")->required();
  command->add_option("reference", options->reference, "The reference image (EXR)")->required();
  command->add_option("--heatmap", options->heatmap, "Write a false-colour error map (PNG)");
  command->add_option("--heatmap-metric", options->heatmap_metric, "Per-pixel error shown in the heat map")
      ->check(CLI::IsMember({"flip", "abs", "rel"}))
      ->capture_default_str();
  command->add_option("--heatmap-max", options->heatmap_max,
                      "Error shown at full scale (default: 1 for FLIP, else the map's maximum)")
      ->check(CLI::NonNegativeNumber);
  command->add_flag("--json", options->json,
                    "Print one JSON object: rmse, rel_mse, psnr (null if identical), max_abs, ssim, flip");
  command->callback([&action, options] { action = [options] { return run_compare(*options); }; });
}

}  // namespace facet::cli
