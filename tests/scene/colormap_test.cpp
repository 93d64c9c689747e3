// Colour maps: the built-in tables decode the shipped CSVs, interpolation and steps between
// control points, the domain, and the construction errors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

#include "common/error.hpp"
#include "scene/colormap.hpp"

namespace facet {
namespace {

// sRGB decoding written out here (IEC 61966-2-1), independent of image/srgb.hpp.
double decode(double e) { return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4); }

std::vector<glm::dvec3> csv_entries(const std::string& name) {
  std::ifstream in(std::string(FACET_SOURCE_DIR) + "/data/colormaps/" + name + ".csv");
  std::vector<glm::dvec3> entries;
  for (std::string line; std::getline(in, line);) {
    glm::dvec3 c;
    if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &c.r, &c.g, &c.b) == 3) entries.push_back(c);
  }
  return entries;
}

std::string construction_error(std::vector<double> positions, std::vector<glm::dvec3> colours,
                               glm::dvec2 domain = {0, 1}) {
  try {
    Colormap(std::move(positions), std::move(colours), Colormap::Interpolation::Linear, domain);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Colormap, BuiltinsAreTheDecodedCsvEntriesInterpolatedLinearly) {
  for (const char* name : {"viridis", "magma", "inferno", "plasma"}) {
    const std::vector<glm::dvec3> entries = csv_entries(name);
    ASSERT_EQ(entries.size(), 256u) << name;
    const Colormap map = builtin_colormap(name);
    for (int i = 0; i < 255; ++i) {
      for (double f : {0.0, 0.25, 0.5, 0.9}) {
        const double t = (i + f) / 255.0;
        const glm::dvec3 lo(decode(entries[i].r), decode(entries[i].g), decode(entries[i].b));
        const glm::dvec3 hi(decode(entries[i + 1].r), decode(entries[i + 1].g), decode(entries[i + 1].b));
        const glm::dvec3 expected = lo + f * (hi - lo);
        // t = (i + f)/255 recovers f to a few ulp of 255: 1e-12 is far above that, far below a colour step.
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(map.at(t)[k], expected[k], 1e-12) << name << " " << t;
      }
    }
    const glm::dvec3 last(decode(entries[255].r), decode(entries[255].g), decode(entries[255].b));
    EXPECT_EQ(map.at(1.0), last);
    EXPECT_EQ(map.at(7.0), last);
    EXPECT_EQ(map.at(-1.0), map.at(0.0));
  }
  EXPECT_THROW(builtin_colormap("jet"), Error);
}

TEST(Colormap, StepsHoldEachColourUntilTheNextPosition) {
  const Colormap map({0.0, 0.3, 0.7}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, Colormap::Interpolation::Steps);
  EXPECT_EQ(map.at(-5.0), glm::dvec3(1, 0, 0));
  EXPECT_EQ(map.at(0.0), glm::dvec3(1, 0, 0));
  EXPECT_EQ(map.at(std::nextafter(0.3, 0.0)), glm::dvec3(1, 0, 0));
  EXPECT_EQ(map.at(0.3), glm::dvec3(0, 1, 0));
  EXPECT_EQ(map.at(0.69), glm::dvec3(0, 1, 0));
  EXPECT_EQ(map.at(0.7), glm::dvec3(0, 0, 1));
  EXPECT_EQ(map.at(1e300), glm::dvec3(0, 0, 1));
  EXPECT_EQ(map.at(std::numeric_limits<double>::quiet_NaN()), glm::dvec3(1, 0, 0));
  // Evenly spaced positions take the division path: the boundaries must still be exact.
  const Colormap even({0.0, 0.1, 0.2, 0.3}, {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}},
                      Colormap::Interpolation::Steps);
  for (int i = 0; i < 3; ++i) {
    const double p = even.positions()[static_cast<size_t>(i) + 1];
    EXPECT_EQ(even.at(p).r, i + 1.0);
    EXPECT_EQ(even.at(std::nextafter(p, 0.0)).r, i);
  }
}

TEST(Colormap, LinearPointsAndDomain) {
  const Colormap map({-1.0, 0.5, 4.0}, {{0, 0, 0}, {1, 2, 3}, {1, 0, 0}}, Colormap::Interpolation::Linear,
                     {10.0, 20.0});
  // value 12.5 -> t = 0.25, in the segment [-1, 0.5] at f = 1.25/1.5 = 5/6.
  const glm::dvec3 c = map.at(12.5);
  EXPECT_NEAR(c.r, 5.0 / 6.0, 1e-15);
  EXPECT_NEAR(c.g, 10.0 / 6.0, 1e-15);
  EXPECT_NEAR(c.b, 15.0 / 6.0, 1e-15);
  const glm::dvec3 d = map.at(10.0 + 10.0 * 2.25);  // t = 2.25: halfway from 0.5 to 4
  EXPECT_NEAR(d.r, 1.0, 1e-15);
  EXPECT_NEAR(d.g, 1.0, 1e-15);
  EXPECT_NEAR(d.b, 1.5, 1e-15);
  EXPECT_EQ(map.max_component(), 3.0);
}

TEST(Colormap, ConstructionErrors) {
  EXPECT_EQ(construction_error({0.0}, {{0, 0, 0}}), "a colour map needs at least 2 control points");
  EXPECT_EQ(construction_error({0.0, 1.0}, {{0, 0, 0}}), "a colour map needs one colour per position");
  EXPECT_EQ(construction_error({0.0, 0.0}, {{0, 0, 0}, {1, 1, 1}}), "colour map positions must increase strictly");
  EXPECT_EQ(construction_error({0.0, std::numeric_limits<double>::infinity()}, {{0, 0, 0}, {1, 1, 1}}),
            "colour map positions must be finite");
  EXPECT_EQ(construction_error({0.0, 1.0}, {{0, -1, 0}, {1, 1, 1}}), "colour map colours must be finite and >= 0");
  EXPECT_EQ(construction_error({0.0, 1.0}, {{0, 0, 0}, {1, 1, 1}}, {1.0, 1.0}),
            "a colour map domain [lo, hi] needs finite lo < hi");
}

}  // namespace
}  // namespace facet
