#include "image/image_comparison.hpp"

#include <cmath>

#include "image/flip.hpp"
#include "image/metrics.hpp"
#include "image/ssim.hpp"

namespace facet {

ImageComparison compare_images(const Image& test, const Image& reference) {
  check_comparable(test, reference);
  ImageComparison c;
  c.rmse = rmse(test, reference);
  c.rel_mse = relative_mse(test, reference);
  c.psnr = psnr(test, reference);
  c.max_abs = max_abs_error(test, reference);
  if (test.width >= kSsimWindow && test.height >= kSsimWindow) c.ssim = ssim(test, reference);
  c.flip = flip(test, reference);
  return c;
}

std::vector<std::pair<std::string, double>> named_metrics(const ImageComparison& c) {
  return {{"rmse", c.rmse},
          {"rel_mse", c.rel_mse},
          {"psnr", c.psnr},
          {"max_abs", c.max_abs},
          {"ssim", c.ssim.value_or(std::nan(""))},
          {"flip", c.flip}};
}

nlohmann::json to_json(const ImageComparison& c) {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& [name, value] : named_metrics(c))
    json[name] = std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
  return json;
}

}  // namespace facet
