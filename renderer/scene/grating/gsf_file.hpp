// Gwyddion Simple Field (.gsf) height maps, the plain format AFM software exports: an ASCII header
// "Gwyddion Simple Field 1.0" of `Key = Value` lines (XRes, YRes, XReal, YReal in metres, ZUnits),
// NUL padding to a multiple of 4 bytes, then XRes * YRes little-endian float32 heights, row-major.
#pragma once

#include <filesystem>
#include <vector>

namespace facet::diffraction {

struct GsfField {
  int x_res = 0, y_res = 0;
  double x_real_m = 0.0, y_real_m = 0.0;  // physical size
  std::vector<double> values;             // in the file's z unit
  double z_unit_m = 1.0;                  // metres per z unit ("m", "um", "nm", or absent = m)
};

// Throws facet::Error naming the file on a malformed header, a missing key or a short data block.
GsfField read_gsf(const std::filesystem::path& path);

}  // namespace facet::diffraction
