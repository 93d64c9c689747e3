// Every metric of `facet compare` for one test image against its reference, computed in one place so
// `facet compare --json` and `facet bench` report the same numbers (docs/image_metrics.md).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/image.hpp"

namespace facet {

struct ImageComparison {
  double rmse = 0.0;
  double rel_mse = 0.0;
  double psnr = 0.0;  // dB; +inf for identical images
  double max_abs = 0.0;
  std::optional<double> ssim;  // undefined for images smaller than the SSIM window
  double flip = 0.0;
};

// Throws facet::Error as check_comparable does.
ImageComparison compare_images(const Image& test, const Image& reference);

// Each metric under its `facet compare --json` name, in that order; an undefined SSIM is NaN, the PSNR
// of identical images +inf. Thresholds (`compare --fail`) are checked against these.
std::vector<std::pair<std::string, double>> named_metrics(const ImageComparison& comparison);

// {rmse, rel_mse, psnr, max_abs, ssim, flip}; JSON has no infinity, so an infinite PSNR and an
// undefined SSIM are written as null.
nlohmann::json to_json(const ImageComparison& comparison);

}  // namespace facet
