// The comparison sheet without the CLI: its size follows the layout, each panel shows its picture (the
// preview's tone mapping) and heat map where the layout puts them, and every label strip has text.
#include "image/compare_sheet.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "common/error.hpp"
#include "image/flip.hpp"
#include "image/heatmap.hpp"
#include "image/png_io.hpp"
#include "image/test_images.hpp"

namespace facet {
namespace {

// The sheet's text colour: pure light grey, which neither the test pictures (tinted) nor magma contain.
constexpr Rgb8 kText = {235, 235, 235};

Image gradient(int width, int height, glm::vec3 tint) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.set(x, y, tint * (0.1f + 0.8f * static_cast<float>(x + y) / (width + height)));
  return image;
}

struct Sheet {
  std::vector<SheetImage> tests;
  std::vector<ImageComparison> errors;
  SheetImage reference;
  std::vector<std::vector<std::string>> labels;
  Rgb8Image picture;
};

Sheet make_sheet(int width, int height) {
  Sheet sheet;
  sheet.reference = {gradient(width, height, {0.9f, 0.6f, 0.3f}), {{"facet:method", std::string("reference")}}, "ref"};
  sheet.tests.push_back({test::noisy(sheet.reference.image, 0.05f, 1), {}, "noisy"});
  sheet.tests.push_back({test::noisy(sheet.reference.image, 0.2f, 2), {}, "noisier"});
  for (const SheetImage& test : sheet.tests) {
    sheet.errors.push_back(compare_images(test.image, sheet.reference.image));
    sheet.labels.push_back(test_label(test, sheet.errors.back()));
  }
  sheet.labels.push_back(reference_label(sheet.reference));
  sheet.picture = compare_sheet(sheet.tests, sheet.errors, sheet.reference);
  return sheet;
}

int text_pixels(const Rgb8Image& image, int x0, int y0, int width, int height) {
  int count = 0;
  for (int y = y0; y < y0 + height; ++y)
    for (int x = x0; x < x0 + width; ++x) count += image.at(x, y) == kText;
  return count;
}

void expect_pasted(const Rgb8Image& sheet, const Rgb8Image& picture, int x0, int y0, const std::string& what) {
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x)
      ASSERT_EQ(sheet.at(x0 + x, y0 + y), picture.at(x, y)) << what << " at " << x << "," << y;
}

TEST(CompareSheet, LabelsSayMethodTimeAndError) {
  const SheetImage timed{
      Image(1, 1),
      {{"facet:method", std::string("filtered")}, {"facet:gpu_ms", 62.43}, {"facet:render_ms", 410.2}},
      "frame"};
  ImageComparison error;
  error.rmse = 0.012345;
  error.flip = 0.0814;
  EXPECT_EQ(test_label(timed, error),
            (std::vector<std::string>{"filtered  gpu 62.4 ms  wall 410 ms", "RMSE 0.0123  FLIP 0.0814"}));
  // A PNG (no metadata) is named by its file and its times are left out.
  EXPECT_EQ(test_label({Image(1, 1), {}, "naive"}, error)[0], "naive");
  const SheetImage reference{
      Image(1, 1),
      {{"facet:method", std::string("reference")}, {"facet:grid", std::int64_t{32}}, {"facet:render_ms", 12034.0}},
      "ref"};
  EXPECT_EQ(reference_label(reference)[0], "reference  grid 32  wall 12034 ms");
}

TEST(CompareSheet, SizeFollowsTheLayout) {
  const Sheet sheet = make_sheet(32, 18);
  const SheetLayout layout = sheet_layout(32, 18, sheet.labels);
  EXPECT_EQ(layout.columns, 3);
  EXPECT_EQ(layout.label_lines, 2);
  EXPECT_GE(layout.column_width, 32);
  // Columns of margin + column, and rows of label strip, picture, heat-map label and heat map.
  EXPECT_EQ(sheet.picture.width, layout.margin + 3 * (layout.column_width + layout.margin));
  EXPECT_EQ(sheet.picture.height,
            layout.margin + 2 * layout.line_height + 18 + layout.margin + layout.line_height + 18 + layout.margin);
  EXPECT_EQ(sheet.picture.width, layout.width);
  EXPECT_EQ(sheet.picture.height, layout.height);
}

TEST(CompareSheet, PanelsShowPreviewsAndFlipMapsWhereTheLayoutSays) {
  const Sheet sheet = make_sheet(32, 18);
  const SheetLayout layout = sheet_layout(32, 18, sheet.labels);
  for (int i = 0; i < 2; ++i) {
    const int x = layout.column_x(i);
    expect_pasted(sheet.picture, preview_rgb8(sheet.tests[i].image), x, layout.picture_y(), "test picture");
    const ScalarImage map = flip_map(sheet.tests[i].image, sheet.reference.image);
    expect_pasted(sheet.picture, Rgb8Image(32, 18, heatmap_rgb8(map, 1.0)), x, layout.heatmap_y(), "heat map");
  }
  expect_pasted(sheet.picture, preview_rgb8(sheet.reference.image), layout.column_x(2), layout.picture_y(),
                "reference picture");
}

TEST(CompareSheet, EveryLabelStripHasText) {
  const Sheet sheet = make_sheet(32, 18);
  const SheetLayout layout = sheet_layout(32, 18, sheet.labels);
  for (int column = 0; column < 3; ++column) {
    const int x = layout.column_x(column);
    const int strip_height = layout.picture_y() - layout.label_y();
    EXPECT_GT(text_pixels(sheet.picture, x, layout.label_y(), layout.column_width, strip_height), 50) << column;
    const int heatmap_label =
        text_pixels(sheet.picture, x, layout.heatmap_label_y(), layout.column_width, layout.line_height);
    if (column < 2)
      EXPECT_GT(heatmap_label, 20) << column;
    else
      EXPECT_EQ(heatmap_label, 0) << "no heat map under the reference";
  }
}

// 1300 px is reduced by the smallest integer factor that fits 640: 3, to ceil(1300 / 3) = 434.
TEST(CompareSheet, WidePicturesAreReduced) {
  const Sheet sheet = make_sheet(1300, 4);
  const SheetLayout layout = sheet_layout(434, 2, sheet.labels);
  EXPECT_EQ(sheet.picture.width, layout.width);
  EXPECT_EQ(sheet.picture.height, layout.height);
}

TEST(CompareSheet, RefusesMissingTestsMismatchedCountsAndSizes) {
  const Sheet sheet = make_sheet(16, 12);
  EXPECT_THROW(compare_sheet({}, {}, sheet.reference), Error);
  EXPECT_THROW(compare_sheet(sheet.tests, {sheet.errors[0]}, sheet.reference), Error);
  const SheetImage smaller{Image(16, 11), {}, "smaller"};
  EXPECT_THROW(compare_sheet({smaller}, {sheet.errors[0]}, sheet.reference), Error);
}

}  // namespace
}  // namespace facet
