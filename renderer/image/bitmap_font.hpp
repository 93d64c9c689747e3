// A 5x7 bitmap font for printable ASCII, so facet can label the pictures it writes (comparison sheets)
// without a font library.
#pragma once

#include <string_view>

#include "image/rgb8_image.hpp"

namespace facet {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = kGlyphWidth + 1;  // one blank column between characters
inline constexpr char kFirstGlyph = ' ', kLastGlyph = '~';

// Whether pixel (x, y) of character c's glyph is lit (top-left origin, x < kGlyphWidth, y < kGlyphHeight).
// A character outside ' '..'~' is drawn as '?'.
bool glyph_pixel(char c, int x, int y);

// Width in pixels of `text` drawn at `scale`, without the blank column after its last character.
int text_width(std::string_view text, int scale = 1);

// Draws `text` on one line with its top-left corner at (x, y), each glyph pixel a scale x scale block
// in `colour`. Pixels outside the image are skipped, so text may run off any edge.
void draw_text(Rgb8Image& image, int x, int y, std::string_view text, Rgb8 colour, int scale = 1);

}  // namespace facet
