// Where and how a frame is written: the EXR (atomically) and an sRGB PNG preview beside it.
#pragma once

#include <filesystem>
#include <string>

#include "image/exr_io.hpp"
#include "image/image.hpp"

namespace facet::frames {

struct FrameFile {
  std::filesystem::path path;       // must end in .exr
  std::string pixel_type = "half";  // "half" or "float"
  double exposure = 0.0;            // of the preview, in stops
  bool preview = true;
};

// Creates the folder, writes the EXR atomically and, unless disabled, the PNG preview (same stem).
void write_frame(const FrameFile& file, const Image& image, const ExrMetadata& metadata);

}  // namespace facet::frames
