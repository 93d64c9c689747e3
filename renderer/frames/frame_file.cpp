#include "frames/frame_file.hpp"

#include "common/error.hpp"
#include "image/png_io.hpp"

namespace facet::frames {

void write_frame(const FrameFile& file, const Image& image, const ExrMetadata& metadata) {
  if (file.path.extension() != ".exr") throw Error(file.path.string() + ": the output must be an .exr file");
  write_exr(file.path, image, metadata, file.pixel_type == "float" ? ExrPixelType::Float : ExrPixelType::Half);
  if (file.preview) write_png_preview(std::filesystem::path(file.path).replace_extension(".png"), image, file.exposure);
}

}  // namespace facet::frames
