// The quick start's pictures (tools/showcase.sh, README "Quick start"), made small: the showcase frame
// and its comparison sheet of naive, filtered and the reference, whose printed errors are those of
// `facet compare` and whose pixels are the sheet built from the same frames.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "image/compare_sheet.hpp"
#include "image/exr_io.hpp"
#include "image/image_comparison.hpp"
#include "image/png_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

const std::string kShowcase = (fs::path(FACET_SOURCE_DIR) / "tools" / "showcase.sh").string();

SheetImage read_sheet_image(const fs::path& path) {
  SheetImage image;
  image.image = read_exr(path, &image.metadata);
  image.stem = path.stem().string();
  return image;
}

TEST(Showcase, WritesThePictureAndASheetOfWhatCompareMeasures) {
  test::TempDir dir;
  // Picture 48 wide, comparison frames 40x23, reference grid 2: the quick start's steps at a small size.
  const auto r = run_command("bash " + kShowcase + " " + kFacet + " " + dir.path().string() + " 48 40 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("facet: picture: " + (dir / "default.png").string()), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("facet: comparison: " + (dir / "default_compare.png").string()), std::string::npos) << r.out;
  ExrMetadata picture_metadata;
  EXPECT_EQ(read_exr(dir / "default.exr", &picture_metadata).width, 48);
  EXPECT_EQ(std::get<std::string>(picture_metadata.at("facet:method")), "filtered");
  EXPECT_TRUE(fs::exists(dir / "default.png"));

  const fs::path frames = dir / "default_compare";
  const fs::path naive = frames / "naive.exr", filtered = frames / "filtered.exr", reference = frames / "reference.exr";
  // What it printed is what two separate compares print.
  const std::string separate = run_command(kFacet + " compare " + naive.string() + " " + reference.string()).out +
                               run_command(kFacet + " compare " + filtered.string() + " " + reference.string()).out;
  EXPECT_NE(r.out.find(separate), std::string::npos) << r.out << "\nexpected:\n" << separate;

  // The sheet holds three labelled panels: it is, pixel for pixel, the sheet of those three frames.
  const std::vector<SheetImage> tests = {read_sheet_image(naive), read_sheet_image(filtered)};
  const SheetImage truth = read_sheet_image(reference);
  EXPECT_EQ(std::get<std::string>(tests[0].metadata.at("facet:method")), "naive");
  EXPECT_EQ(std::get<std::string>(truth.metadata.at("facet:method")), "reference");
  const std::vector<ImageComparison> errors = {compare_images(tests[0].image, truth.image),
                                               compare_images(tests[1].image, truth.image)};
  const Rgb8Image expected = compare_sheet(tests, errors, truth);
  EXPECT_EQ(sheet_layout(40, 23, {test_label(tests[0], errors[0]), test_label(tests[1], errors[1]),
                                  reference_label(truth)})
                .columns,
            3);
  const PngImage sheet = read_png(dir / "default_compare.png");
  ASSERT_EQ(sheet.width, expected.width);
  ASSERT_EQ(sheet.height, expected.height);
  ASSERT_EQ(sheet.channels, 3);
  int differing = 0;
  for (std::size_t i = 0; i < expected.bytes.size(); ++i)
    differing += std::lround(sheet.values[i] * 255.0f) != expected.bytes[i];
  EXPECT_EQ(differing, 0);
}

}  // namespace
}  // namespace facet
