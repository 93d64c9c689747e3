// False-colour heat maps of per-pixel errors, written as PNG.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "image/image.hpp"

namespace facet {

// values / max_value through the magma map (0 = black-purple, max_value and above = pale yellow),
// as 8-bit sRGB bytes, 3 per pixel. max_value must be positive and finite.
std::vector<std::uint8_t> heatmap_rgb8(const ScalarImage& values, double max_value);

void write_heatmap_png(const std::filesystem::path& path, const ScalarImage& values, double max_value);

}  // namespace facet
