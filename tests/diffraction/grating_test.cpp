// Gratings as data: procedural patterns against their formulas, height maps with units, and every
// bad field a one-line error.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>

#include "common/error.hpp"
#include "diffraction_cases.hpp"
#include "image/exr_io.hpp"
#include "image/png_io.hpp"

#include <png.h>

namespace facet {
namespace {

using test::grating;
using test::kPi;

TEST(Grating, SinusoidSamplesTheFormula) {
  const auto g = grating(R"({"type":"sinusoid","period_nm":1300,"amplitude_nm":80,"size_um":26,"samples":320})");
  EXPECT_EQ(g.samples, 320);
  EXPECT_DOUBLE_EQ(g.sample_nm, 81.25);
  EXPECT_DOUBLE_EQ(g.period_nm(), 26000.0);
  EXPECT_DOUBLE_EQ(g.coherence_nm, 26000.0);  // default: one patch
  for (int y : {0, 7})
    for (int x : {0, 3, 4, 100})
      EXPECT_NEAR(g.height_nm[y * 320 + x], 80 * std::sin(2 * kPi * x * 81.25 / 1300), 1e-12);
}

TEST(Grating, RectangularCrossedAndFingers) {
  const auto r =
      grating(R"({"type":"rectangular","period_nm":1000,"amplitude_nm":50,"size_um":10,"samples":200,"duty":0.3})");
  const double high = std::count(r.height_nm.begin(), r.height_nm.end(), 50.0);
  EXPECT_DOUBLE_EQ(high / r.height_nm.size(), 0.3);
  EXPECT_EQ(std::count(r.height_nm.begin(), r.height_nm.end(), -50.0) + high, double(r.height_nm.size()));

  const auto c = grating(R"({"type":"crossed","period_nm":[1000,2000],"amplitude_nm":60,"size_um":4,"samples":64})");
  const double d = c.sample_nm;
  for (int y : {0, 5, 33})
    for (int x : {0, 9, 50})
      EXPECT_NEAR(c.height_nm[y * 64 + x], 30 * (std::sin(2 * kPi * x * d / 1000) + std::sin(2 * kPi * y * d / 2000)),
                  1e-12);

  const auto f = grating(
      R"({"type":"fingers","period_nm":1000,"amplitude_nm":70,"size_um":8,"samples":128,"finger_length_nm":2000,"duty":0.5})");
  const auto [lo, hi] = std::minmax_element(f.height_nm.begin(), f.height_nm.end());
  EXPECT_GE(*lo, 0.0);
  EXPECT_LE(*hi, 70.0);
  EXPECT_GT(*hi, 60.0);
  // Periodic: x -> x + period (16 samples), y -> y + 2 finger lengths (64 samples), wrapping the patch.
  for (int y = 0; y < 128; y += 5)
    for (int x = 0; x < 128; x += 3) {
      EXPECT_NEAR(f.height_nm[y * 128 + x], f.height_nm[y * 128 + (x + 16) % 128], 1e-9);
      EXPECT_NEAR(f.height_nm[y * 128 + x], f.height_nm[((y + 64) % 128) * 128 + x], 1e-9);
    }
}

// A height map with its units: EXR values times nm_per_unit, spacing nm_per_sample.
// A sample count that leaves a period a fraction of samples is raised to the next one that does
// not (brute force over the counts in between), with one note line; a whole count, or one whose
// next whole count passes 4096 samples, is kept, silently. The raised field repeats with each period exactly.
TEST(Grating, SamplesAreRaisedUntilEveryPeriodIsWhole) {
  auto whole = [](int M, double size_nm, double period_nm) {
    const double samples = M * period_nm / size_nm;
    return std::abs(samples - std::round(samples)) < 1e-9;
  };
  testing::internal::CaptureStderr();
  const auto c = grating(R"({"type":"crossed","period_nm":[1200,2000],"amplitude_nm":60,"size_um":12,"samples":96})");
  const std::string note = testing::internal::GetCapturedStderr();
  ASSERT_EQ(c.samples, 120);
  EXPECT_DOUBLE_EQ(c.sample_nm, 100.0);
  for (int M = 96; M < 120; ++M) EXPECT_FALSE(whole(M, 12000, 1200) && whole(M, 12000, 2000)) << M;
  EXPECT_EQ(note,
            "facet: note: test: grating.samples 96 raised to 120, so every period spans a whole number of samples\n");
  for (int y = 0; y < 120; y += 7)
    for (int x = 0; x < 120; x += 5) {
      EXPECT_NEAR(c.height_nm[y * 120 + x], c.height_nm[y * 120 + (x + 12) % 120], 1e-9);
      EXPECT_NEAR(c.height_nm[y * 120 + x], c.height_nm[((y + 20) % 120) * 120 + x], 1e-9);
    }
  EXPECT_EQ(grating(R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":60,"size_um":8,"samples":64})").samples, 65);
  const auto f = grating(
      R"({"type":"fingers","period_nm":1000,"amplitude_nm":70,"size_um":6,"samples":40,"finger_length_nm":1000})");
  EXPECT_EQ(f.samples, 42);  // 6 periods along x, 3 along y (two finger lengths)
  testing::internal::CaptureStderr();
  EXPECT_EQ(grating(R"({"type":"crossed","period_nm":[1000,2000],"amplitude_nm":60,"size_um":4,"samples":64})").samples,
            64);
  // 239 and 240 periods: the first whole count, 57360, passes 4096.
  EXPECT_EQ(grating(R"({"type":"crossed","period_nm":[100,99.58333333333333],"amplitude_nm":60,"size_um":23.9,)"
                    R"("samples":1000})")
                .samples,
            1000);
  // A bad grating gets its one-line error and no note.
  EXPECT_THROW(grating(R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":60,"size_um":8,"samples":64,"colour":1})"),
               Error);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(Grating, HeightMapFromExr) {
  const auto dir = std::filesystem::temp_directory_path() / "facet_grating_test";
  std::filesystem::create_directories(dir);
  Image image(16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) image.set(x, y, glm::vec3(0.25f * float((x + 2 * y) % 5)));
  write_exr(dir / "h.exr", image, {}, ExrPixelType::Float);
  std::ofstream(dir / "g.json")
      << R"({"type":"heightmap","path":"h.exr","nm_per_sample":50,"nm_per_unit":40,"channel":"R"})";
  const auto g = diffraction::parse_grating((dir / "g.json").string());  // path relative to the JSON file
  EXPECT_EQ(g.samples, 16);
  EXPECT_DOUBLE_EQ(g.sample_nm, 50.0);
  EXPECT_DOUBLE_EQ(g.height_nm[3 * 16 + 2], 40 * 0.25 * ((2 + 6) % 5));
  // Colour PNGs are not height maps; non-square maps are rejected.
  std::vector<std::uint8_t> rgb(16 * 16 * 3, 7);
  write_png_rgb8(dir / "c.png", 16, 16, rgb);
  EXPECT_THROW(diffraction::parse_grating(R"({"type":"heightmap","path":")" + (dir / "c.png").string() +
                                          R"(","nm_per_sample":50,"nm_per_unit":1})"),
               Error);
  write_exr(dir / "wide.exr", Image(16, 8), {}, ExrPixelType::Float);
  EXPECT_THROW(diffraction::parse_grating(R"({"type":"heightmap","path":")" + (dir / "wide.exr").string() +
                                          R"(","nm_per_sample":50,"nm_per_unit":1,"channel":"R"})"),
               Error);
  std::filesystem::remove_all(dir);
}

// A 16-bit grey PNG (written with libpng's simplified API): height = integer code * nm_per_unit.
TEST(Grating, HeightMapFromSixteenBitPng) {
  const auto path = std::filesystem::temp_directory_path() / "facet_grating_test_16.png";
  std::vector<png_uint_16> codes(32 * 32);
  for (size_t i = 0; i < codes.size(); ++i) codes[i] = static_cast<png_uint_16>((i * 2654435761u) % 65536);
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = image.height = 32;
  image.format = PNG_FORMAT_LINEAR_Y;
  ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, codes.data(), 0, nullptr)) << image.message;
  const auto g = diffraction::parse_grating(R"({"type":"heightmap","path":")" + path.string() +
                                            R"(","nm_per_sample":25,"nm_per_unit":0.01})");
  ASSERT_EQ(g.samples, 32);
  for (size_t i : {size_t(0), size_t(5), size_t(777), size_t(1023)})
    EXPECT_NEAR(g.height_nm[i], 0.01 * codes[i], 1e-9) << i;
  std::filesystem::remove(path);
}

// A Gwyddion Simple Field with its own units: 8 x 8 samples over 4 um (500 nm each), heights in um.
TEST(Grating, HeightMapFromGsf) {
  const auto path = std::filesystem::temp_directory_path() / "facet_grating_test.gsf";
  std::string header = "Gwyddion Simple Field 1.0\nXRes = 8\nYRes = 8\nXReal = 4e-06\nYReal = 4e-06\nZUnits = um\n";
  header.append(4 - header.size() % 4, '\0');
  std::vector<float> values(64);
  for (int i = 0; i < 64; ++i) values[i] = 0.01f * float(i % 7);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(header.data(), std::streamsize(header.size()));
    out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  }
  const auto g = diffraction::parse_grating(R"({"type":"heightmap","path":")" + path.string() + R"("})");
  EXPECT_EQ(g.samples, 8);
  EXPECT_DOUBLE_EQ(g.sample_nm, 500.0);
  for (int i : {0, 3, 13, 63}) EXPECT_NEAR(g.height_nm[i], 1000.0 * values[i], 1e-9) << i;
  // Its units come from the file: giving them again is an error, as is a truncated data block.
  EXPECT_THROW(diffraction::parse_grating(R"({"type":"heightmap","path":")" + path.string() + R"(","nm_per_unit":1})"),
               Error);
  std::filesystem::resize_file(path, header.size() + 100);
  EXPECT_THROW(diffraction::parse_grating(R"({"type":"heightmap","path":")" + path.string() + R"("})"), Error);
  std::filesystem::remove(path);
}

TEST(Grating, BadFieldsAreOneLineErrors) {
  const std::string ok = R"("period_nm":1000,"amplitude_nm":50,"size_um":10,"samples":200)";
  for (
      const std::string& json : {
          std::string(R"({"type":"zigzag",)") + ok + "}",
          std::string(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":50,"samples":200})"),  // no size
          std::string(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":50,"size_um":10,"samples":4})"),
          std::string(
              R"({"type":"sinusoid","period_nm":1300,"amplitude_nm":50,"size_um":10,"samples":200})"),  // 7.7 periods
          std::string(
              R"({"type":"sinusoid","period_nm":100,"amplitude_nm":50,"size_um":10,"samples":200})"),  // 2
                                                                                                       // samples/period
          std::string(R"({"type":"sinusoid","period_nm":1000,"amplitude_nm":-5,"size_um":10,"samples":200})"),
          std::string(R"({"type":"rectangular","duty":1.0,)") + ok + "}",
          std::string(R"({"type":"sinusoid","amplitde_nm":3,)") + ok + "}",   // unknown key
          std::string(R"({"type":"sinusoid","coherence_um":1,)") + ok + "}",  // below a quarter patch
          std::string(R"({"type":"sinusoid","ior":0.5,)") + ok + "}",
          std::string(R"({"type":"crossed","period_nm":[1000],"amplitude_nm":50,"size_um":10,"samples":200})"),
          std::string(R"({"type":"fingers","finger_length_nm":3000,)") + ok + "}",  // 10 um / 6 um not whole
          std::string(R"({"type":"heightmap","path":"/nonexistent.exr","nm_per_sample":1,"nm_per_unit":1})"),
          std::string(R"({"type":"heightmap","path":"/nonexistent.exr"})"),  // no units
          std::string(R"({"type":"sinusoid",)"),
      }) {
    try {
      diffraction::parse_grating(json);
      ADD_FAILURE() << "accepted " << json;
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_FALSE(message.empty());
    }
  }
  EXPECT_THROW(diffraction::parse_grating("/nonexistent/grating.json"), Error);
}

}  // namespace
}  // namespace facet
