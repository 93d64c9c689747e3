#include "scene/grating/height_map_file.hpp"

#include <cmath>

#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"
#include "scene/grating/gsf_file.hpp"

namespace facet::diffraction {

namespace {

double required(const std::optional<double>& unit, const std::filesystem::path& path, const char* key) {
  if (!unit) throw Error(path.string() + ": " + key + " is required for a height map without units");
  return *unit;
}

}  // namespace

HeightMap read_height_map(const std::filesystem::path& path, const HeightMapUnits& units) {
  HeightMap map;
  int width = 0, height = 0;
  const std::string ext = path.extension().string();
  if (ext == ".exr") {
    ScalarImage image = read_exr_scalar(path, units.channel);
    width = image.width;
    height = image.height;
    const double nm_per_unit = required(units.nm_per_unit, path, "nm_per_unit");
    for (float v : image.values) map.height_nm.push_back(v * nm_per_unit);
    map.nm_per_sample = required(units.nm_per_sample, path, "nm_per_sample");
  } else if (ext == ".png") {
    PngImage image = read_png(path);
    if (image.channels != 1) throw Error(path.string() + ": a height map PNG must be grey, not RGB");
    width = image.width;
    height = image.height;
    const double codes = std::ldexp(1.0, image.bit_depth) - 1.0;  // values are code / codes
    const double nm_per_unit = required(units.nm_per_unit, path, "nm_per_unit");
    for (float v : image.values) map.height_nm.push_back(std::round(v * codes) * nm_per_unit);
    map.nm_per_sample = required(units.nm_per_sample, path, "nm_per_sample");
  } else if (ext == ".gsf") {
    if (units.nm_per_sample || units.nm_per_unit)
      throw Error(path.string() + ": a .gsf file states its own units; drop nm_per_sample and nm_per_unit");
    const GsfField f = read_gsf(path);
    width = f.x_res;
    height = f.y_res;
    map.nm_per_sample = 1e9 * f.x_real_m / f.x_res;
    if (std::abs(1e9 * f.y_real_m / f.y_res - map.nm_per_sample) > 1e-6 * map.nm_per_sample)
      throw Error(path.string() + ": the samples must be square (XReal / XRes = YReal / YRes)");
    for (double v : f.values) map.height_nm.push_back(v * f.z_unit_m * 1e9);
  } else {
    throw Error(path.string() + ": a height map must be .exr, .png or .gsf");
  }
  if (width != height)
    throw Error(path.string() + ": a height map must be square, got " + std::to_string(width) + "x" +
                std::to_string(height));
  for (double h : map.height_nm)
    if (!std::isfinite(h)) throw Error(path.string() + ": the height map holds a non-finite value");
  if (!(map.nm_per_sample > 0.0)) throw Error(path.string() + ": the sample spacing must be positive");
  map.samples = width;
  return map;
}

}  // namespace facet::diffraction
