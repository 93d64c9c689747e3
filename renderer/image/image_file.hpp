// Reading an image someone wants judged, whatever it was saved as (`facet compare`).
#pragma once

#include <filesystem>

#include "image/exr_io.hpp"
#include "image/image.hpp"

namespace facet {

// By extension: .exr as stored (scene-linear RGB); .png decoded from sRGB to linear, grey expanded to
// RGB, so a PNG and the EXR it previews compare alike. Throws facet::Error for any other extension.
// If `metadata` is given it receives an EXR's attributes (read_exr) and is left empty for a PNG.
Image read_image(const std::filesystem::path& path, ExrMetadata* metadata = nullptr);

}  // namespace facet
