#include "diffraction/height_map_file.hpp"

#include <cmath>

#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"

namespace facet::diffraction {

std::vector<double> read_height_map(const std::filesystem::path& path, const HeightMapUnits& units, int& samples) {
  std::vector<double> heights;
  int width = 0, height = 0;
  const std::string ext = path.extension().string();
  if (ext == ".exr") {
    ScalarImage image = read_exr_scalar(path, units.channel);
    width = image.width;
    height = image.height;
    for (float v : image.values) heights.push_back(v * units.nm_per_unit);
  } else if (ext == ".png") {
    PngImage image = read_png(path);
    if (image.channels != 1) throw Error(path.string() + ": a height map PNG must be grey, not RGB");
    width = image.width;
    height = image.height;
    const double codes = std::ldexp(1.0, image.bit_depth) - 1.0;  // values are code / codes
    for (float v : image.values) heights.push_back(std::round(v * codes) * units.nm_per_unit);
  } else {
    throw Error(path.string() + ": a height map must be .exr or .png");
  }
  if (width != height) throw Error(path.string() + ": a height map must be square, got " + std::to_string(width) +
                                   "x" + std::to_string(height));
  for (double h : heights)
    if (!std::isfinite(h)) throw Error(path.string() + ": the height map holds a non-finite value");
  samples = width;
  return heights;
}

}  // namespace facet::diffraction
