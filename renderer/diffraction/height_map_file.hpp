// Measured height fields (e.g. AFM scans) from image files with their physical units.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace facet::diffraction {

struct HeightMapUnits {
  double nm_per_sample;  // lateral spacing
  double nm_per_unit;    // EXR: nm per stored value; PNG: nm per integer code step
  std::string channel;   // EXR channel to read
};

// Row-major heights in nm of a square map; `samples` receives its side. .exr or .png (8/16-bit
// grey). Throws facet::Error on unreadable or non-square files and on non-finite heights.
std::vector<double> read_height_map(const std::filesystem::path& path, const HeightMapUnits& units, int& samples);

}  // namespace facet::diffraction
