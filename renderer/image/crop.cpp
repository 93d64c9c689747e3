#include "image/crop.hpp"

#include <algorithm>
#include <string>

#include "common/error.hpp"

namespace facet {

Image crop(const Image& image, const PixelRect& rect) {
  // Compared as differences so that huge values cannot overflow the sums.
  const bool inside = rect.width > 0 && rect.height > 0 && rect.x >= 0 && rect.y >= 0 &&
                      rect.x <= image.width - rect.width && rect.y <= image.height - rect.height;
  if (!inside)
    throw Error("crop " + std::to_string(rect.x) + "," + std::to_string(rect.y) + "," + std::to_string(rect.width) +
                "," + std::to_string(rect.height) + " is not inside the " + std::to_string(image.width) + "x" +
                std::to_string(image.height) + " image");
  Image region(rect.width, rect.height);
  for (int y = 0; y < rect.height; ++y) {
    const auto row = image.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(image.index(rect.x, rect.y + y));
    std::copy(row, row + 3 * rect.width, region.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(region.index(0, y)));
  }
  return region;
}

}  // namespace facet
