#include "image/image_file.hpp"

#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"
#include "image/srgb.hpp"

namespace facet {

namespace {

Image linear_from_png(const PngImage& png) {
  Image image(png.width, png.height);
  for (std::size_t pixel = 0; pixel < image.pixel_count(); ++pixel)
    for (int c = 0; c < 3; ++c) {
      const float encoded = png.values[pixel * png.channels + (png.channels == 3 ? c : 0)];
      image.rgb[3 * pixel + c] = static_cast<float>(srgb_decode(encoded));
    }
  return image;
}

}  // namespace

Image read_image(const std::filesystem::path& path, ExrMetadata* metadata) {
  if (metadata != nullptr) metadata->clear();
  const auto extension = path.extension();
  if (extension == ".exr") return read_exr(path, metadata);
  if (extension == ".png") return linear_from_png(read_png(path));
  throw Error(path.string() + ": not an image facet reads (.exr or .png)");
}

}  // namespace facet
