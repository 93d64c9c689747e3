// A frame's files: the EXR and its sRGB preview, which is encoded beside the EXR's write and stored only
// once the EXR is.
#include "frames/frame_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

#include "common/error.hpp"
#include "image/png_io.hpp"
#include "image/srgb.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace frame_file_test {

// A gradient with values below, inside and above [0, 1], so every branch of the encoding is crossed.
Image gradient(int width, int height) {
  Image image(width, height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = -0.1f + 1.3f * static_cast<float>(i) / image.rgb.size();
  return image;
}

TEST(FrameFile, PreviewHoldsTheSrgbCodesOfTheFrame) {
  test::TempDir dir;
  const Image image = gradient(37, 11);
  frames::write_frame({.path = dir / "f.exr", .exposure = 1.0}, image, {});
  ASSERT_TRUE(std::filesystem::exists(dir / "f.exr"));
  const PngImage png = read_png(dir / "f.png");
  ASSERT_EQ(png.width, 37);
  ASSERT_EQ(png.channels, 3);
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    ASSERT_EQ(std::lround(png.values[i] * 255.0f), srgb_display8(2.0 * image.rgb[i])) << "sample " << i;
}

TEST(FrameFile, NoPreviewWhenTheExrFails) {
  test::TempDir dir;
  Image image = gradient(8, 8);
  image.rgb[5] = std::numeric_limits<float>::quiet_NaN();  // refused by the EXR writer
  EXPECT_THROW(frames::write_frame({.path = dir / "f.exr"}, image, {}), Error);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(FrameFile, NoPreviewWhenAskedForNone) {
  test::TempDir dir;
  frames::write_frame({.path = dir / "f.exr", .preview = false}, gradient(4, 4), {});
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"f.exr"});
}

}  // namespace frame_file_test
}  // namespace facet
