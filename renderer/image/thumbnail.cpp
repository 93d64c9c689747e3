#include "image/thumbnail.hpp"

#include <algorithm>

namespace facet {

namespace {

// Box-filters `channels` interleaved floats per pixel by `factor` (>= 1).
std::vector<float> box_reduce(const std::vector<float>& in, int width, int height, int channels, int factor,
                              int out_width, int out_height) {
  std::vector<float> out(static_cast<std::size_t>(out_width) * out_height * channels, 0.0f);
  for (int oy = 0; oy < out_height; ++oy)
    for (int ox = 0; ox < out_width; ++ox) {
      const int x1 = std::min(width, (ox + 1) * factor), y1 = std::min(height, (oy + 1) * factor);
      for (int c = 0; c < channels; ++c) {
        double sum = 0.0;
        for (int y = oy * factor; y < y1; ++y)
          for (int x = ox * factor; x < x1; ++x) sum += in[(static_cast<std::size_t>(y) * width + x) * channels + c];
        const int count = (x1 - ox * factor) * (y1 - oy * factor);
        out[(static_cast<std::size_t>(oy) * out_width + ox) * channels + c] = static_cast<float>(sum / count);
      }
    }
  return out;
}

int reduction_factor(int width, int max_width) { return std::max(1, (width + max_width - 1) / max_width); }

// Picture is Image (3 samples per pixel in .rgb) or ScalarImage (1 in .values).
template <typename Picture>
Picture reduced(const Picture& image, std::vector<float> Picture::*samples, int channels, int max_width) {
  const int f = reduction_factor(image.width, max_width);
  if (f == 1) return image;
  Picture out;
  out.width = (image.width + f - 1) / f;
  out.height = (image.height + f - 1) / f;
  out.*samples = box_reduce(image.*samples, image.width, image.height, channels, f, out.width, out.height);
  return out;
}

}  // namespace

Image thumbnail(const Image& image, int max_width) { return reduced(image, &Image::rgb, 3, max_width); }

ScalarImage thumbnail(const ScalarImage& image, int max_width) {
  return reduced(image, &ScalarImage::values, 1, max_width);
}

}  // namespace facet
