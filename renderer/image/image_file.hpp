// Reading an image someone wants judged, whatever it was saved as (`facet compare`).
#pragma once

#include <filesystem>

#include "image/image.hpp"

namespace facet {

// By extension: .exr as stored (scene-linear RGB); .png decoded from sRGB to linear, grey expanded to
// RGB, so a PNG and the EXR it previews compare alike. Throws facet::Error for any other extension.
Image read_image(const std::filesystem::path& path);

}  // namespace facet
