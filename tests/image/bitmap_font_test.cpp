// The bitmap font: every printable glyph is drawn and distinct, and text lands where it is asked to,
// scaled, clipped at the image's edges.
#include "image/bitmap_font.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace facet {
namespace {

constexpr Rgb8 kInk = {255, 200, 0};

std::vector<bool> glyph_bits(char c) {
  std::vector<bool> bits;
  for (int y = 0; y < kGlyphHeight; ++y)
    for (int x = 0; x < kGlyphWidth; ++x) bits.push_back(glyph_pixel(c, x, y));
  return bits;
}

int inked(const Rgb8Image& image) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) count += image.at(x, y) == kInk;
  return count;
}

TEST(BitmapFont, EveryPrintableGlyphIsLitAndNoTwoAreAlike) {
  std::set<std::vector<bool>> seen;
  for (char c = kFirstGlyph; c <= kLastGlyph; ++c) {
    const std::vector<bool> bits = glyph_bits(c);
    const bool lit = std::count(bits.begin(), bits.end(), true) > 0;
    EXPECT_EQ(lit, c != ' ') << "'" << c << "'";
    EXPECT_TRUE(seen.insert(bits).second) << "'" << c << "' looks like an earlier glyph";
  }
  EXPECT_EQ(seen.size(), 95u);
}

TEST(BitmapFont, UnprintableCharactersDrawAsQuestionMarks) {
  for (char c : {'\n', '\0', '\x7f', static_cast<char>(0xc3)}) EXPECT_EQ(glyph_bits(c), glyph_bits('?'));
}

// Each lit glyph pixel becomes a scale x scale block at the glyph's place; nothing else changes.
TEST(BitmapFont, DrawsEachGlyphPixelAsAScaledBlock) {
  const std::string text = "fR7";
  const int scale = 3, x0 = 2, y0 = 4;
  Rgb8Image image(80, 30);
  draw_text(image, x0, y0, text, kInk, scale);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const int column = (x - x0) / scale, row = (y - y0) / scale;
      const int glyph = column / kGlyphAdvance;
      const bool inside = x >= x0 && y >= y0 && glyph < static_cast<int>(text.size()) && row < kGlyphHeight &&
                          column % kGlyphAdvance < kGlyphWidth;
      const bool lit = inside && glyph_pixel(text[glyph], column % kGlyphAdvance, row);
      EXPECT_EQ(image.at(x, y) == kInk, lit) << x << "," << y;
    }
}

// 'H' lights its last column, so its right edge ends the text: text_width says where.
TEST(BitmapFont, TextWidthEndsAtTheLastGlyphColumn) {
  Rgb8Image image(40, 10);
  draw_text(image, 0, 0, "HH", kInk, 2);
  int rightmost = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (image.at(x, y) == kInk) rightmost = std::max(rightmost, x);
  EXPECT_EQ(text_width("HH", 2), rightmost + 1);
  EXPECT_EQ(text_width("", 2), 0);
}

// Text running off any edge draws exactly the part inside (the same pixels as on a larger image) and
// writes nothing outside (ASan would report it).
TEST(BitmapFont, ClipsAtTheImageEdges) {
  const int pad = 40;
  for (int dx : {-25, -4, 0, 3, 9})
    for (int dy : {-12, -2, 0, 4, 7}) {
      Rgb8Image small(10, 8);
      Rgb8Image large(10 + 2 * pad, 8 + 2 * pad);
      draw_text(small, dx, dy, "W@g", kInk, 2);
      draw_text(large, pad + dx, pad + dy, "W@g", kInk, 2);
      for (int y = 0; y < small.height; ++y)
        for (int x = 0; x < small.width; ++x)
          ASSERT_EQ(small.at(x, y), large.at(pad + x, pad + y)) << dx << "," << dy << " at " << x << "," << y;
      if (dx == 0 && dy == 0) {
        EXPECT_GT(inked(small), 0);
        EXPECT_LT(inked(small), inked(large)) << "the text is wider than the small image";
      }
    }
}

}  // namespace
}  // namespace facet
