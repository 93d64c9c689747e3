// The comparison sheet of `facet compare --sheet`: test images and their reference side by side, each
// under a label strip naming its method, its time and its error, and each test's FLIP heat map beneath
// it (docs/image_metrics.md, "Comparison sheets").
#pragma once

#include <string>
#include <vector>

#include "image/exr_io.hpp"
#include "image/image.hpp"
#include "image/image_comparison.hpp"
#include "image/rgb8_image.hpp"

namespace facet {

// One image of the sheet as read from its file.
struct SheetImage {
  Image image;           // scene-linear, already cropped to the compared region
  ExrMetadata metadata;  // facet:method, facet:gpu_ms, facet:render_ms, facet:grid; empty for a PNG
  std::string stem;      // the file name without its extension: the label when facet:method is absent
};

// Wider pictures are box-filtered down (thumbnail) so a sheet of several panels stays readable.
inline constexpr int kSheetPictureMaxWidth = 640;

// Where everything goes. Columns: one per test, then the reference. Rows: each column's label strip
// and picture, then under each test its heat map's label and the heat map, all separated by margins.
struct SheetLayout {
  int columns = 0;
  int text_scale = 1;  // glyph pixels per font pixel: 2 once pictures are wide enough to dwarf 5x7 text
  int margin = 0;
  int line_height = 0;
  int column_width = 0;  // the picture or the widest line of text, whichever is wider
  int picture_width = 0, picture_height = 0;
  int label_lines = 0;
  int width = 0, height = 0;

  int column_x(int column) const { return margin + column * (column_width + margin); }
  int label_y() const { return margin; }
  int picture_y() const { return label_y() + label_lines * line_height; }
  int heatmap_label_y() const { return picture_y() + picture_height + margin; }
  int heatmap_y() const { return heatmap_label_y() + line_height; }
};

// The label strips' text, one string per line. A test: its method (facet:method, else the file stem)
// with gpu and wall times when its metadata has them, then "RMSE r  FLIP f". The reference: its method
// with facet:grid and wall time, then a line saying the errors are against it.
std::vector<std::string> test_label(const SheetImage& test, const ImageComparison& error);
std::vector<std::string> reference_label(const SheetImage& reference);

// The heat maps' label.
inline constexpr const char* kSheetHeatmapLabel = "FLIP error map, 0 to 1";

// The layout for pictures of picture_width x picture_height (already reduced) and these label strips.
SheetLayout sheet_layout(int picture_width, int picture_height, const std::vector<std::vector<std::string>>& labels);

// The sheet of tests[i], each compared with `reference` as errors[i] (compare_images, so the labels show
// the numbers `facet compare` prints). Pictures use the PNG previews' tone mapping (preview_rgb8, exposure
// 0, the view FLIP judges). Throws facet::Error if there is no test, a count differs or a size differs.
Rgb8Image compare_sheet(const std::vector<SheetImage>& tests, const std::vector<ImageComparison>& errors,
                        const SheetImage& reference);

}  // namespace facet
