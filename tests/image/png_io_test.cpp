// PNG previews against hand-computed sRGB codes, 8-bit round trips, and 8/16-bit grey and RGB files
// made by a third-party tool (oiiotool) read back to the exact stored codes.
#include "image/png_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "image/srgb.hpp"
#include "support/child_process.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

using test::TempDir;

std::vector<int> codes(const PngImage& image, int max_code) {
  std::vector<int> result;
  for (float v : image.values) result.push_back(static_cast<int>(std::lround(v * max_code)));
  return result;
}

TEST(Srgb, KnownValuesAndInverse) {
  // Codes worked out by hand from IEC 61966-2-1: 0.5 -> 1.055*0.5^(1/2.4)-0.055 = 0.7354 -> 187.5 -> 188;
  // 0.18 -> 0.4614 -> 117.7 -> 118; 0.001 is on the linear segment: 12.92*0.001*255 = 3.29 -> 3.
  EXPECT_EQ(srgb_display8(0.5), 188);
  EXPECT_EQ(srgb_display8(0.18), 118);
  EXPECT_EQ(srgb_display8(0.001), 3);
  EXPECT_EQ(srgb_display8(1.0), 255);
  EXPECT_EQ(srgb_display8(7.0), 255);
  EXPECT_EQ(srgb_display8(-1.0), 0);
  EXPECT_EQ(srgb_display8(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(srgb_display8(std::numeric_limits<double>::infinity()), 255);
  // The two pieces meet at the breakpoint to within the rounding of the published constants (~1e-7).
  EXPECT_NEAR(srgb_encode(0.0031308), 1.055 * std::pow(0.0031308, 1 / 2.4) - 0.055, 1e-7);
  for (int i = 0; i <= 1000; ++i) {
    const double x = i / 1000.0;
    EXPECT_NEAR(srgb_decode(srgb_encode(x)), x, 1e-12) << x;
  }
}

TEST(PngIo, PreviewIsSrgbEncodedWithExposure) {
  TempDir dir;
  Image image(4, 1);
  image.set(0, 0, glm::vec3(0.5f, 0.18f, 0.001f));
  image.set(1, 0, glm::vec3(0.25f, 0.09f, 0.0005f));  // one stop down: +1 stop must give pixel 0's codes
  image.set(2, 0, glm::vec3(-3.0f, 2.0f, std::numeric_limits<float>::quiet_NaN()));
  image.set(3, 0, glm::vec3(0.0f, 1.0f, 0.5f));
  write_png_preview(dir / "p.png", image, 1.0);
  const PngImage png = read_png(dir / "p.png");
  ASSERT_EQ(png.width, 4);
  ASSERT_EQ(png.height, 1);
  ASSERT_EQ(png.channels, 3);
  EXPECT_EQ(png.bit_depth, 8);
  // With exposure +1: pixel 0 doubles (1.0, 0.36, 0.002), pixel 1 becomes (0.5, 0.18, 0.001).
  // 0.36 -> 1.055*0.36^(1/2.4)-0.055 = 0.6343 -> 161.7 -> 162; 0.002 -> 12.92*0.002*255 = 6.6 -> 7.
  EXPECT_EQ(codes(png, 255), (std::vector<int>{255, 162, 7, 188, 118, 3, 0, 255, 0, 0, 255, 255}));
}

TEST(PngIo, PreviewMatchesOiiotoolColourConversion) {
  TempDir dir;
  Image image(37, 23);
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> value(-0.1f, 1.3f);
  for (float& v : image.rgb) v = value(rng);
  write_exr(dir / "linear.exr", image, {}, ExrPixelType::Float);
  write_png_preview(dir / "ours.png", image);
  const auto convert = test::run_command("oiiotool " + (dir / "linear.exr").string() +
                                         " --colorconvert linear sRGB -d uint8 -o " + (dir / "theirs.png").string());
  ASSERT_EQ(convert.exit_code, 0) << convert.out;
  // OIIO rounds through its own float path; one code (1/255) is the most two correct encoders may differ.
  const auto diff =
      test::run_command("idiff -fail 0.004 " + (dir / "ours.png").string() + " " + (dir / "theirs.png").string());
  EXPECT_EQ(diff.exit_code, 0) << diff.out;
  // The same comparison must fail for a preview one stop too bright (the check can fail).
  write_png_preview(dir / "bright.png", image, 1.0);
  const auto wrong =
      test::run_command("idiff -fail 0.004 " + (dir / "bright.png").string() + " " + (dir / "theirs.png").string());
  EXPECT_NE(wrong.exit_code, 0) << wrong.out;
}

TEST(PngIo, Rgb8RoundTripIsExact) {
  TempDir dir;
  const int width = 17, height = 5;
  std::vector<std::uint8_t> bytes(3 * width * height);
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>((i * 37 + 11) % 256);
  write_png_rgb8(dir / "c.png", width, height, bytes);
  const PngImage png = read_png(dir / "c.png");
  ASSERT_EQ(png.width, width);
  ASSERT_EQ(png.height, height);
  ASSERT_EQ(png.channels, 3);
  EXPECT_EQ(codes(png, 255), std::vector<int>(bytes.begin(), bytes.end()));
}

// A grey ramp of exact codes written by oiiotool from a float EXR (R channel only), at 8 or 16 bits.
void expect_oiiotool_codes_read_back(const std::string& format, int max_code, const std::string& channels,
                                     int expected_channels) {
  TempDir dir;
  const std::vector<int> ramp = max_code == 65535 ? std::vector<int>{0, 1, 255, 256, 4097, 32768, 65534, 65535}
                                                  : std::vector<int>{0, 1, 2, 127, 128, 200, 254, 255};
  Image image(static_cast<int>(ramp.size()), 1);
  for (std::size_t i = 0; i < ramp.size(); ++i) {
    const float v = static_cast<float>(ramp[i]) / static_cast<float>(max_code);
    image.set(i, glm::vec3(v, v, 1.0f - v));
  }
  write_exr(dir / "ramp.exr", image, {}, ExrPixelType::Float);
  const auto made = test::run_command("oiiotool " + (dir / "ramp.exr").string() + " --ch " + channels + " -d " +
                                      format + " -o " + (dir / "ramp.png").string());
  ASSERT_EQ(made.exit_code, 0) << made.out;
  const PngImage png = read_png(dir / "ramp.png");
  ASSERT_EQ(png.channels, expected_channels);
  EXPECT_EQ(png.bit_depth, max_code == 65535 ? 16 : 8);
  std::vector<int> expected;
  for (int code : ramp) {
    expected.push_back(code);
    if (expected_channels == 3) expected.insert(expected.end(), {code, max_code - code});
  }
  EXPECT_EQ(codes(png, max_code), expected);
}

TEST(PngIo, ReadsGrey16) { expect_oiiotool_codes_read_back("uint16", 65535, "R", 1); }
TEST(PngIo, ReadsGrey8) { expect_oiiotool_codes_read_back("uint8", 255, "R", 1); }
TEST(PngIo, ReadsRgb16) { expect_oiiotool_codes_read_back("uint16", 65535, "R,G,B", 3); }
TEST(PngIo, ReadsRgbaAsRgb) { expect_oiiotool_codes_read_back("uint8", 255, "R,G,B,A=1.0", 3); }
// Opaque alpha: OIIO treats alpha as associated and would divide the stored grey by it.
TEST(PngIo, ReadsGreyAlphaAsGrey) { expect_oiiotool_codes_read_back("uint16", 65535, "R,A=1.0", 1); }

TEST(PngIo, BadInputsGiveOneLineErrorNamingThePath) {
  TempDir dir;
  std::ofstream(dir / "garbage.png") << "definitely not a png";
  write_png_rgb8(dir / "whole.png", 64, 64, std::vector<std::uint8_t>(3 * 64 * 64, 77));
  std::ifstream in(dir / "whole.png", std::ios::binary);
  const std::string whole{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::ofstream(dir / "truncated.png", std::ios::binary) << whole.substr(0, whole.size() / 2);
  for (const char* name : {"missing.png", "garbage.png", "truncated.png"}) {
    SCOPED_TRACE(name);
    try {
      read_png(dir / name);
      FAIL() << "no error";
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find((dir / name).string()), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  }
}

// A text chunk that claims 1.7 GB in a file of a few hundred bytes: read_png refuses it in one line
// without letting libpng allocate and clear the claimed length first (before the fix the read
// took 1.7 GB). Read in a child process so that its peak resident size can be measured.
TEST(PngIo, HostileChunkLengthCostsNoMemory) {
  TempDir dir;
  write_png_rgb8(dir / "whole.png", 8, 8, std::vector<std::uint8_t>(3 * 8 * 8, 77));
  std::ifstream in(dir / "whole.png", std::ios::binary);
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  // After the signature (8) and IHDR (4 + 4 + 13 + 4): tEXt of length 0x67000000, a few bytes of it.
  const std::string hostile = std::string("\x67\x00\x00\x00tEXtComment", 15) + std::string(64, 'x');
  bytes = bytes.substr(0, 33) + hostile;
  std::ofstream(dir / "hostile.png", std::ios::binary) << bytes;
  const test::ChildRun run = test::run_in_child([&] {
    try {
      read_png(dir / "hostile.png");
    } catch (const Error& e) {
      return std::string(e.what()).find('\n') == std::string::npos ? 0 : 2;
    }
    return 1;
  });
  EXPECT_EQ(run.exit_code, 0);                // 1: accepted, 2: not one line
  EXPECT_LT(run.rss_growth_kib, 256 * 1024);  // 1.7 GB before the fix
}

TEST(PngIo, FailedWritesLeaveNothing) {
  TempDir dir;
  std::ofstream(dir / "plain").put('x');  // a file where a folder should be: it cannot be created
  EXPECT_THROW(write_png_rgb8(dir / "plain" / "x.png", 1, 1, std::vector<std::uint8_t>(3)), Error);
  EXPECT_THROW(write_png_rgb8(dir / "short.png", 2, 2, std::vector<std::uint8_t>(11)), Error);
  EXPECT_THROW(write_png_rgb8(dir / "empty.png", 0, 3, {}), Error);
  EXPECT_THROW(write_png_preview(dir / "plain" / "x.png", Image(1, 1)), Error);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"plain"});
}

}  // namespace
}  // namespace facet
