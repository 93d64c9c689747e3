// Measured height fields (e.g. AFM scans) from image files with their physical units.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace facet::diffraction {

// Units given by the user: required for .exr and .png, which carry none; must be absent for .gsf,
// whose header states them.
struct HeightMapUnits {
  std::optional<double> nm_per_sample;  // lateral spacing
  std::optional<double> nm_per_unit;    // EXR: nm per stored value; PNG: nm per integer code step
  std::string channel;                  // EXR channel to read
};

struct HeightMap {
  int samples = 0;  // the map is samples x samples
  double nm_per_sample = 0.0;
  std::vector<double> height_nm;  // row-major
};

// .exr, .png (8/16-bit grey) or .gsf (Gwyddion Simple Field). Throws facet::Error on unreadable or
// non-square files, missing or superfluous units and non-finite heights.
HeightMap read_height_map(const std::filesystem::path& path, const HeightMapUnits& units);

}  // namespace facet::diffraction
