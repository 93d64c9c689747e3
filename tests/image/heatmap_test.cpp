// The compiled-in magma table against the CSV read here independently, and heat map PNGs.
#include "image/heatmap.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/error.hpp"
#include "image/colormap.hpp"
#include "image/png_io.hpp"
#include "image/srgb.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

std::vector<glm::dvec3> csv_entries() {
  std::ifstream in(std::string(FACET_SOURCE_DIR) + "/data/colormaps/magma.csv");
  std::vector<glm::dvec3> entries;
  std::string line;
  std::getline(in, line);  // citation
  std::getline(in, line);  // r,g,b
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    glm::dvec3 c;
    fields >> c.r >> c.g >> c.b;
    entries.push_back(c);
  }
  return entries;
}

TEST(Colormap, HitsEveryEntryAndInterpolatesBetween) {
  const auto entries = csv_entries();
  ASSERT_EQ(entries.size(), 256u);
  for (int k = 0; k < 256; ++k)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(magma(k / 255.0)[c], entries[k][c], 1e-6) << k;
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(magma(127.5 / 255.0)[c], (entries[127][c] + entries[128][c]) / 2, 1e-6);
    EXPECT_NEAR(magma(-3.0)[c], entries[0][c], 1e-6);
    EXPECT_NEAR(magma(42.0)[c], entries[255][c], 1e-6);
    EXPECT_NEAR(magma(std::numeric_limits<double>::quiet_NaN())[c], entries[255][c], 1e-6);
  }
}

TEST(Colormap, LuminanceIncreasesMonotonically) {
  // The property that makes magma readable as a scale: relative luminance of the decoded entries rises.
  const auto entries = csv_entries();
  double previous = -1.0;
  for (const auto& c : entries) {
    const double y = 0.2126 * srgb_decode(c.r) + 0.7152 * srgb_decode(c.g) + 0.0722 * srgb_decode(c.b);
    EXPECT_GT(y, previous);
    previous = y;
  }
}

TEST(Heatmap, PngCarriesTheScaledColours) {
  test::TempDir dir;
  const auto entries = csv_entries();
  ScalarImage error(3, 2);
  error.values = {0.0f, 0.5f, 1.0f, 2.0f, -1.0f, 0.25f};  // scale 2: t = 0, 1/4, 1/2, 1, 0, 1/8
  write_heatmap_png(dir / "h.png", error, 2.0);
  const PngImage png = read_png(dir / "h.png");
  ASSERT_EQ(png.channels, 3);
  const double t[] = {0.0, 0.25, 0.5, 1.0, 0.0, 0.125};
  for (int p = 0; p < 6; ++p) {
    const double position = t[p] * 255;
    const int lower = std::min(static_cast<int>(position), 254);
    for (int c = 0; c < 3; ++c) {
      const double expected = entries[lower][c] + (position - lower) * (entries[lower + 1][c] - entries[lower][c]);
      EXPECT_NEAR(png.values[3 * p + c], expected, 0.5 / 255 + 1e-6) << p << " " << c;
    }
  }
  EXPECT_THROW(heatmap_rgb8(error, 0.0), Error);
  EXPECT_THROW(heatmap_rgb8(error, std::numeric_limits<double>::infinity()), Error);
}

}  // namespace
}  // namespace facet
