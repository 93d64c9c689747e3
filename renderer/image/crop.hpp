// A rectangle of an image, to judge one region of a frame (`facet compare --crop`).
#pragma once

#include "image/image.hpp"

namespace facet {

struct PixelRect {
  int x = 0, y = 0;  // top-left corner; rows count from the top like Image
  int width = 0, height = 0;
};

// The pixels of `rect`. Throws facet::Error if the rectangle is empty or not inside the image.
Image crop(const Image& image, const PixelRect& rect);
ScalarImage crop(const ScalarImage& image, const PixelRect& rect);

}  // namespace facet
