// Small previews (the report, comparison sheets): images box-filtered down to a maximum width.
#pragma once

#include "image/image.hpp"

namespace facet {

// The image reduced by the smallest integer factor f that makes width / f <= max_width, each output
// pixel the mean of an f x f block (edge blocks clipped); unchanged when it is narrow enough.
Image thumbnail(const Image& image, int max_width);
ScalarImage thumbnail(const ScalarImage& image, int max_width);

}  // namespace facet
