// `facet compare --sheet`: several tests against one reference print exactly what separate compares
// print, the sheet is laid out with a labelled panel per image, and bad input leaves no sheet.
#include <algorithm>
#include <filesystem>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "image/compare_sheet.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

// A frame with structure, brightened by `gain` and shifted by `shift` pixels: tests that differ from
// the reference in different amounts.
Image pattern(int width, int height, float gain, int shift) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float stripe = ((x + shift) / 3 + y / 4) % 2 ? 0.8f : 0.15f;
      image.set(x, y, gain * glm::vec3(stripe, 0.5f * stripe, 0.3f));
    }
  return image;
}

class CompareSheetCli : public ::testing::Test {
 protected:
  void SetUp() override {
    write_exr(naive_, pattern(32, 18, 1.1f, 1),
              {{"facet:method", std::string("naive")}, {"facet:gpu_ms", 3.5}, {"facet:render_ms", 120.0}},
              ExrPixelType::Float);
    write_exr(filtered_, pattern(32, 18, 1.02f, 0), {{"facet:method", std::string("filtered")}}, ExrPixelType::Float);
    write_exr(reference_, pattern(32, 18, 1.0f, 0),
              {{"facet:method", std::string("reference")}, {"facet:grid", std::int64_t{8}}}, ExrPixelType::Float);
  }
  std::string images() const { return naive_.string() + " " + filtered_.string() + " " + reference_.string(); }

  test::TempDir dir_;
  fs::path naive_ = dir_ / "naive.exr", filtered_ = dir_ / "filtered.exr", reference_ = dir_ / "reference.exr";
  fs::path sheet_ = dir_ / "sheet" / "compare.png";
};

TEST_F(CompareSheetCli, PrintsWhatSeparateComparesPrint) {
  for (const std::string flags : {" --json", " --json --crop 4,2,24,14", ""}) {
    auto r = run_command(kFacet + " compare " + images() + " --sheet " + sheet_.string() + flags);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string separate =
        run_command(kFacet + " compare " + naive_.string() + " " + reference_.string() + flags).out +
        run_command(kFacet + " compare " + filtered_.string() + " " + reference_.string() + flags).out;
    EXPECT_EQ(r.out, separate) << flags;
    EXPECT_TRUE(fs::exists(sheet_));
  }
}

// The sheet of the 32x18 frames: its size is the layout's for the printed numbers' labels, and every
// panel's label strip holds text.
TEST_F(CompareSheetCli, SheetHasALabelledPanelPerImage) {
  auto r = run_command(kFacet + " compare " + images() + " --sheet " + sheet_.string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::vector<std::string>> labels;
  std::istringstream lines(r.out);
  for (const fs::path& test : {naive_, filtered_}) {
    std::string line;
    std::getline(lines, line);
    const auto printed = nlohmann::json::parse(line);
    ImageComparison error;
    error.rmse = printed.at("rmse").get<double>();
    error.flip = printed.at("flip").get<double>();
    ExrMetadata metadata;
    read_exr(test, &metadata);
    labels.push_back(test_label({Image(), metadata, test.stem().string()}, error));
  }
  EXPECT_EQ(labels[0][0], "naive  gpu 3.5 ms  wall 120 ms");
  EXPECT_EQ(labels[1][0], "filtered");
  ExrMetadata reference_metadata;
  read_exr(reference_, &reference_metadata);
  labels.push_back(reference_label({Image(), reference_metadata, "reference"}));
  EXPECT_EQ(labels[2][0], "reference  grid 8");

  const SheetLayout layout = sheet_layout(32, 18, labels);
  const PngImage sheet = read_png(sheet_);
  EXPECT_EQ(sheet.width, layout.width);
  EXPECT_EQ(sheet.height, layout.height);
  ASSERT_EQ(sheet.channels, 3);
  for (int column = 0; column < 3; ++column) {
    int lit = 0;  // the text's light grey (235)
    for (int y = layout.label_y(); y < layout.picture_y(); ++y)
      for (int x = layout.column_x(column); x < layout.column_x(column) + layout.column_width; ++x) {
        const float* pixel = &sheet.values[3 * (static_cast<std::size_t>(y) * sheet.width + x)];
        lit += pixel[0] > 0.9f && pixel[0] == pixel[1] && pixel[1] == pixel[2];
      }
    EXPECT_GT(lit, 50) << "column " << column;
  }
}

TEST_F(CompareSheetCli, FailGatesApplyToEveryTest) {
  // naive (shifted stripes) is far off; filtered only 2% bright.
  auto r = run_command(kFacet + " compare " + images() + " --sheet " + sheet_.string() + " --json --fail 'rmse>0.05'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("facet: compare: failed: " + naive_.string() + ": rmse ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2) << "both still print";
  EXPECT_TRUE(fs::exists(sheet_));
  r = run_command(kFacet + " compare " + images() + " --sheet " + sheet_.string() + " --fail 'rmse>0.001'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;
}

TEST_F(CompareSheetCli, BadInputIsOneLineErrorAndNoSheet) {
  write_exr(dir_ / "small.exr", pattern(30, 18, 1.0f, 0), {}, ExrPixelType::Float);
  const std::string sheet = " --sheet " + sheet_.string();
  const std::vector<std::string> commands = {
      naive_.string() + " " + (dir_ / "missing.exr").string() + " " + reference_.string() + sheet,
      naive_.string() + " " + (dir_ / "small.exr").string() + " " + reference_.string() + sheet,
      images() + " --sheet " + (dir_ / "sheet.jpg").string(),
      images() + sheet + " --heatmap " + (dir_ / "h.png").string(),
      reference_.string() + sheet,
      images(),  // three images without --sheet
  };
  for (const std::string& arguments : commands) {
    auto r = run_command(kFacet + " compare " + arguments);
    EXPECT_NE(r.exit_code, 0) << arguments;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("facet: error: ", 0), 0u) << r.err;
    EXPECT_TRUE(r.out.empty()) << arguments;
    EXPECT_FALSE(fs::exists(sheet_)) << arguments;
    EXPECT_FALSE(fs::exists(dir_ / "sheet.jpg"));
  }
}

}  // namespace
}  // namespace facet
