// 8-bit sRGB-encoded RGB pictures, as a PNG stores them: previews, heat maps, and the comparison sheets
// composed of them and labelled with text.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace facet {

using Rgb8 = std::array<std::uint8_t, 3>;

struct Rgb8Image {
  int width = 0, height = 0;
  std::vector<std::uint8_t> bytes;  // 3 per pixel, top row first (write_png_rgb8's layout)

  Rgb8Image() = default;
  Rgb8Image(int width_, int height_, Rgb8 fill = {0, 0, 0})
      : width(width_), height(height_), bytes(3 * static_cast<std::size_t>(width_) * height_) {
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = fill[i % 3];
  }
  Rgb8Image(int width_, int height_, std::vector<std::uint8_t> bytes_)
      : width(width_), height(height_), bytes(std::move(bytes_)) {}

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  std::size_t offset(int x, int y) const { return 3 * (static_cast<std::size_t>(y) * width + x); }
  Rgb8 at(int x, int y) const { return {bytes[offset(x, y)], bytes[offset(x, y) + 1], bytes[offset(x, y) + 2]}; }
  void set(int x, int y, Rgb8 c) {
    for (int i = 0; i < 3; ++i) bytes[offset(x, y) + i] = c[i];
  }
};

}  // namespace facet
