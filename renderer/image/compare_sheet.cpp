#include "image/compare_sheet.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <variant>

#include "common/error.hpp"
#include "image/bitmap_font.hpp"
#include "image/flip.hpp"
#include "image/heatmap.hpp"
#include "image/png_io.hpp"
#include "image/thumbnail.hpp"

namespace facet {

namespace {

constexpr Rgb8 kBackground = {24, 24, 24};
constexpr Rgb8 kTextColour = {235, 235, 235};

// Three significant digits, whole numbers from 100 up: enough to tell methods apart on a sheet (the
// full values are printed).
std::string short_number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, value >= 100.0 ? "%.0f" : "%.3g", value);
  return text;
}

std::optional<double> metadata_number(const ExrMetadata& metadata, const std::string& key) {
  const auto found = metadata.find(key);
  if (found == metadata.end()) return std::nullopt;
  if (const auto* real = std::get_if<double>(&found->second)) return *real;
  if (const auto* integer = std::get_if<std::int64_t>(&found->second)) return static_cast<double>(*integer);
  return std::nullopt;
}

std::string method_name(const SheetImage& image) {
  const auto found = image.metadata.find("facet:method");
  if (found != image.metadata.end())
    if (const auto* name = std::get_if<std::string>(&found->second)) return *name;
  return image.stem;
}

// "  gpu 62 ms" for facet:gpu_ms; nothing when the image does not say.
std::string metadata_field(const SheetImage& image, const std::string& key, const std::string& word,
                           const std::string& unit) {
  const std::optional<double> value = metadata_number(image.metadata, key);
  return value ? "  " + word + " " + short_number(*value) + unit : "";
}

void paste(Rgb8Image& canvas, const Rgb8Image& picture, int x, int y) {
  for (int py = 0; py < picture.height; ++py)
    for (int px = 0; px < picture.width; ++px) canvas.set(x + px, y + py, picture.at(px, py));
}

void draw_label(Rgb8Image& sheet, const SheetLayout& layout, int x, int y, const std::vector<std::string>& lines) {
  for (std::size_t i = 0; i < lines.size(); ++i)
    draw_text(sheet, x, y + static_cast<int>(i) * layout.line_height, lines[i], kTextColour, layout.text_scale);
}

}  // namespace

std::vector<std::string> test_label(const SheetImage& test, const ImageComparison& error) {
  return {method_name(test) + metadata_field(test, "facet:gpu_ms", "gpu", " ms") +
              metadata_field(test, "facet:render_ms", "wall", " ms"),
          "RMSE " + short_number(error.rmse) + "  FLIP " + short_number(error.flip)};
}

std::vector<std::string> reference_label(const SheetImage& reference) {
  return {method_name(reference) + metadata_field(reference, "facet:grid", "grid", "") +
              metadata_field(reference, "facet:render_ms", "wall", " ms"),
          "errors are against this"};
}

SheetLayout sheet_layout(int picture_width, int picture_height, const std::vector<std::vector<std::string>>& labels) {
  SheetLayout layout;
  layout.columns = static_cast<int>(labels.size());
  layout.text_scale = std::max(1, picture_width / 320);
  layout.margin = 6 * layout.text_scale;
  layout.line_height = (kGlyphHeight + 4) * layout.text_scale;
  layout.picture_width = picture_width;
  layout.picture_height = picture_height;
  layout.column_width = std::max(picture_width, text_width(kSheetHeatmapLabel, layout.text_scale));
  for (const auto& label : labels) {
    layout.label_lines = std::max(layout.label_lines, static_cast<int>(label.size()));
    for (const std::string& line : label)
      layout.column_width = std::max(layout.column_width, text_width(line, layout.text_scale));
  }
  layout.width = layout.column_x(layout.columns);
  layout.height = layout.heatmap_y() + picture_height + layout.margin;
  return layout;
}

Rgb8Image compare_sheet(const std::vector<SheetImage>& tests, const std::vector<ImageComparison>& errors,
                        const SheetImage& reference) {
  if (tests.empty()) throw Error("a comparison sheet needs at least one test image");
  if (errors.size() != tests.size())
    throw Error("comparison sheet: " + std::to_string(tests.size()) + " test images but " +
                std::to_string(errors.size()) + " comparisons");
  std::vector<std::vector<std::string>> labels;
  for (std::size_t i = 0; i < tests.size(); ++i) labels.push_back(test_label(tests[i], errors[i]));
  labels.push_back(reference_label(reference));

  const Rgb8Image reference_picture = preview_rgb8(thumbnail(reference.image, kSheetPictureMaxWidth));
  const SheetLayout layout = sheet_layout(reference_picture.width, reference_picture.height, labels);
  Rgb8Image sheet(layout.width, layout.height, kBackground);
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const int x = layout.column_x(static_cast<int>(i));
    // The FLIP map at full resolution, then reduced like the picture: it shows where the error is.
    const ScalarImage error_map = thumbnail(flip_map(tests[i].image, reference.image), kSheetPictureMaxWidth);
    draw_label(sheet, layout, x, layout.label_y(), labels[i]);
    paste(sheet, preview_rgb8(thumbnail(tests[i].image, kSheetPictureMaxWidth)), x, layout.picture_y());
    draw_label(sheet, layout, x, layout.heatmap_label_y(), {kSheetHeatmapLabel});
    paste(sheet, Rgb8Image(error_map.width, error_map.height, heatmap_rgb8(error_map, 1.0)), x, layout.heatmap_y());
  }
  const int reference_x = layout.column_x(layout.columns - 1);
  draw_label(sheet, layout, reference_x, layout.label_y(), labels.back());
  paste(sheet, reference_picture, reference_x, layout.picture_y());
  return sheet;
}

}  // namespace facet
