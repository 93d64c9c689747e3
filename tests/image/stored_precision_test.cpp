// How far a stored colour may lie from the one written: each bound against real round trips through the
// files facet writes (half and float EXR, 8-bit PNG) and a 16-bit sRGB model, never exceeded and nearly
// reached; and the true error an estimate is judged against, resolved at those bounds.
#include "image/stored_precision.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "image/image_file.hpp"
#include "image/metrics.hpp"
#include "image/png_io.hpp"
#include "image/srgb.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

using test::TempDir;

// Magnitudes spread evenly in log between 2^-30 and 2^15 (half's subnormals to near its largest finite
// value), of either sign, and zero.
std::vector<double> log_spread_values(unsigned seed, int count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> exponent(-30.0, 15.0);
  std::vector<double> values{0.0};
  for (int i = 0; i < count; ++i) values.push_back((i % 2 ? -1.0 : 1.0) * std::exp2(exponent(rng)));
  return values;
}

// The largest |written - read| / bound over the pairs; fails where a difference passes its bound.
double worst_bound_ratio(const std::vector<double>& written, const std::vector<double>& read,
                         const StoredPrecision& precision) {
  double worst = 0.0;
  for (std::size_t i = 0; i < written.size(); ++i) {
    const double bound = rounding_bound(read[i], precision);
    EXPECT_LE(std::abs(written[i] - read[i]), bound) << "value " << written[i] << " read as " << read[i];
    worst = std::max(worst, std::abs(written[i] - read[i]) / bound);
  }
  return worst;
}

Image image_of(const std::vector<double>& values) {
  Image image(static_cast<int>(values.size()), 1);
  for (std::size_t i = 0; i < values.size(); ++i)
    image.rgb[3 * i] = image.rgb[3 * i + 1] = image.rgb[3 * i + 2] = static_cast<float>(values[i]);
  return image;
}

std::vector<double> red_of(const Image& image) {
  std::vector<double> red;
  for (std::size_t i = 0; i < image.pixel_count(); ++i) red.push_back(image.rgb[3 * i]);
  return red;
}

TEST(StoredPrecision, HalfExrRoundingStaysWithinItsBound) {
  TempDir dir;
  const std::vector<double> values = log_spread_values(3, 4000);
  std::vector<double> written;
  for (double v : values) written.push_back(static_cast<float>(v));  // what the writer is given
  write_exr(dir / "h.exr", image_of(written), {}, ExrPixelType::Half);
  const StoredPrecision precision = stored_precision(dir / "h.exr");
  EXPECT_EQ(precision.fraction_bits, kHalfSamples.fraction_bits);
  EXPECT_GT(worst_bound_ratio(written, red_of(read_image(dir / "h.exr")), precision), 0.9);
}

TEST(StoredPrecision, FloatRoundingStaysWithinItsBound) {
  TempDir dir;
  write_exr(dir / "f.exr", image_of({0.5}), {}, ExrPixelType::Float);
  EXPECT_EQ(stored_precision(dir / "f.exr").fraction_bits, kFloatSamples.fraction_bits);
  // A double stored as a float (EXR's float channels hold exactly what the float image holds).
  std::vector<double> written = log_spread_values(5, 4000), read;
  for (double& v : written) v *= std::exp2(-100.0);  // down into float's subnormals too
  for (double v : written) read.push_back(static_cast<float>(v));
  EXPECT_GT(worst_bound_ratio(written, read, kFloatSamples), 0.9);
}

TEST(StoredPrecision, SrgbPngRoundingStaysWithinItsBound) {
  TempDir dir;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> linear(0.0, 1.0);
  std::vector<double> written;
  for (int i = 0; i < 3000; ++i) written.push_back(i % 3 ? linear(rng) : std::pow(linear(rng), 6.0));  // dark too
  std::vector<std::uint8_t> bytes;
  for (double v : written)
    for (int c = 0; c < 3; ++c) bytes.push_back(srgb_display8(v));
  write_png_rgb8(dir / "p.png", static_cast<int>(written.size()), 1, bytes);
  const StoredPrecision precision = stored_precision(dir / "p.png");
  EXPECT_EQ(precision.srgb_bits, 8);
  EXPECT_GT(worst_bound_ratio(written, red_of(read_image(dir / "p.png")), precision), 0.9);
  // 16-bit codes, as a 16-bit PNG holds them.
  std::vector<double> read;
  for (double v : written) read.push_back(srgb_decode(std::round(srgb_encode(v) * 65535.0) / 65535.0));
  EXPECT_GT(worst_bound_ratio(written, read, srgb_samples(16)), 0.9);
}

TEST(StoredPrecision, OtherFilesAreRefusedInOneLine) {
  TempDir dir;
  try {
    stored_precision(dir / "frame.tiff");
    FAIL() << "a .tiff has no precision facet knows";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
  }
}

// An exactly shaded pixel stored in half reads as an error of up to 3e-4 of its value; resolved, it is
// none, while a real difference keeps all but the two roundings.
TEST(ResolvedErrorMap, DifferencesWithinTheRoundingAreNoError) {
  TempDir dir;
  Image truth(64, 1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> value(0.0f, 4.0f);
  for (float& v : truth.rgb) v = value(rng);
  write_exr(dir / "h.exr", truth, {}, ExrPixelType::Half);
  const Image half = read_image(dir / "h.exr");
  const ScalarImage raw = absolute_error_map(truth, half);
  const ScalarImage resolved = resolved_error_map(truth, half, kFloatSamples, kHalfSamples);
  EXPECT_GT(*std::max_element(raw.values.begin(), raw.values.end()), 1e-5f);
  for (float e : resolved.values) EXPECT_EQ(e, 0.0f);

  Image off = truth;
  off.rgb[0] += 0.01f;  // pixel 0's red
  const ScalarImage one = resolved_error_map(off, half, kFloatSamples, kHalfSamples);
  const double expected = (std::abs(double(off.rgb[0]) - half.rgb[0]) - rounding_bound(off.rgb[0], kFloatSamples) -
                           rounding_bound(half.rgb[0], kHalfSamples)) /
                          3.0;
  EXPECT_NEAR(one.values[0], expected, 1e-7);
  EXPECT_GT(one.values[0], 0.003f);
  for (std::size_t p = 1; p < one.pixel_count(); ++p) EXPECT_EQ(one.values[p], 0.0f);
}

}  // namespace
}  // namespace facet
