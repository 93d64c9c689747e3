#include "frames/frame_file.hpp"

#include <future>

#include "common/error.hpp"
#include "image/io_error.hpp"
#include "image/png_io.hpp"

namespace facet::frames {

void write_frame(const FrameFile& file, const Image& image, const ExrMetadata& metadata) {
  if (file.path.extension() != ".exr") throw Error(file.path.string() + ": the output must be an .exr file");
  const std::filesystem::path png_path = std::filesystem::path(file.path).replace_extension(".png");
  // The preview is encoded on a second thread while the EXR is compressed and written (each ~0.1 s at
  // 1280x720), and stored only after the EXR, so a failed frame leaves no new preview.
  std::future<std::vector<std::uint8_t>> png;
  if (file.preview)
    png = std::async(std::launch::async, [&image, exposure = file.exposure] {
      return encode_png_preview(image, exposure);
    });
  write_exr(file.path, image, metadata, file.pixel_type == "float" ? ExrPixelType::Float : ExrPixelType::Half);
  if (!file.preview) return;
  std::vector<std::uint8_t> bytes;
  try {
    bytes = png.get();
  } catch (const std::exception& e) {
    throw io_error(png_path, e.what());
  }
  write_png_file(png_path, bytes);
}

}  // namespace facet::frames
