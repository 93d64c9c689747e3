#include "image/crop.hpp"

#include <algorithm>
#include <string>

#include "common/error.hpp"

namespace facet {

namespace {

void check_inside(const PixelRect& rect, int width, int height) {
  // Compared as differences so that huge values cannot overflow the sums.
  const bool inside = rect.width > 0 && rect.height > 0 && rect.x >= 0 && rect.y >= 0 &&
                      rect.x <= width - rect.width && rect.y <= height - rect.height;
  if (!inside)
    throw Error("crop " + std::to_string(rect.x) + "," + std::to_string(rect.y) + "," + std::to_string(rect.width) +
                "," + std::to_string(rect.height) + " is not inside the " + std::to_string(width) + "x" +
                std::to_string(height) + " image");
}

// Copies the rectangle's rows of `channels` values per pixel from a row-major plane of `width` pixels.
template <class T>
void copy_rows(const std::vector<T>& from, int width, std::vector<T>& to, const PixelRect& rect, int channels) {
  for (int y = 0; y < rect.height; ++y) {
    const auto row = from.begin() + channels * (static_cast<std::ptrdiff_t>(rect.y + y) * width + rect.x);
    std::copy(row, row + channels * rect.width, to.begin() + channels * static_cast<std::ptrdiff_t>(y) * rect.width);
  }
}

}  // namespace

Image crop(const Image& image, const PixelRect& rect) {
  check_inside(rect, image.width, image.height);
  Image region(rect.width, rect.height);
  copy_rows(image.rgb, image.width, region.rgb, rect, 3);
  return region;
}

ScalarImage crop(const ScalarImage& image, const PixelRect& rect) {
  check_inside(rect, image.width, image.height);
  ScalarImage region(rect.width, rect.height);
  copy_rows(image.values, image.width, region.values, rect, 1);
  return region;
}

}  // namespace facet
