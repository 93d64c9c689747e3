#include "image/heatmap.hpp"

#include <cmath>
#include <string>

#include "common/error.hpp"
#include "image/colormap.hpp"
#include "image/png_io.hpp"

namespace facet {

std::vector<std::uint8_t> heatmap_rgb8(const ScalarImage& values, double max_value) {
  if (!(max_value > 0.0) || !std::isfinite(max_value))
    throw Error("heat map scale must be positive and finite, got " + std::to_string(max_value));
  std::vector<std::uint8_t> bytes;
  bytes.reserve(3 * values.pixel_count());
  for (float v : values.values) {
    const glm::vec3 c = magma(v / max_value);
    for (int i = 0; i < 3; ++i) bytes.push_back(static_cast<std::uint8_t>(std::lround(255.0f * c[i])));
  }
  return bytes;
}

void write_heatmap_png(const std::filesystem::path& path, const ScalarImage& values, double max_value) {
  write_png_rgb8(path, values.width, values.height, heatmap_rgb8(values, max_value));
}

}  // namespace facet
