// A periodic scalar field on a regular grid (a height map or a noise texture), in double.
//
// Row-major with row y = 0 first, the layout of EXR scan lines; values wrap at the borders.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

#include "image/exr_io.hpp"

namespace facet::assets {

// The largest side of a generated field (`facet make`, scene textures): 8192^2 doubles are 512 MiB,
// checked before anything is allocated (docs/limits.md).
inline constexpr int kMaxFieldSide = 8192;

struct ScalarField {
  int width = 0, height = 0;
  std::vector<double> values;

  double at(int x, int y) const { return values[static_cast<std::size_t>(y) * width + x]; }
  // Periodic access: any integer x, y.
  double wrapped(long long x, long long y) const {
    long long w = width, h = height;
    return at(static_cast<int>(((x % w) + w) % w), static_cast<int>(((y % h) + h) % h));
  }
};

// Writes the field as grey RGB (R = G = B = value, 32-bit float; read it back with
// read_exr_scalar(path, "R")), atomically, with `metadata` in the header.
void write_scalar_field_exr(const std::filesystem::path& path, const ScalarField& field, const ExrMetadata& metadata);

// Reads such a file back (channel R, widened to double), with its metadata if asked.
ScalarField read_scalar_field_exr(const std::filesystem::path& path, ExrMetadata* metadata = nullptr);

}  // namespace facet::assets
