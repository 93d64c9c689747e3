// `facet make heightfield|noise` end to end: files, metadata, determinism, one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

class MakeCommand : public ::testing::Test {
 protected:
  test::CommandResult facet(const std::string& args) { return test::run_command(kFacet + " " + args); }
  std::string out(const std::string& name) { return (dir_ / name).string(); }
  test::TempDir dir_;
};

std::vector<char> bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), {});
}

TEST_F(MakeCommand, HeightfieldCarriesItsStatistics) {
  auto r = facet("make heightfield -o " + out("a.exr") +
                 " --width 64 --height 48 --texel-size 0.5 --sigma-h 0.2 "
                 "--corr-x 3 --corr-y 2 --angle-deg 20 --seed 9");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata m;
  Image image = read_exr(out("a.exr"), &m);
  ASSERT_EQ(image.width, 64);
  ASSERT_EQ(image.height, 48);
  double sum2 = 0.0;
  for (std::size_t k = 0; k < image.pixel_count(); ++k) sum2 += double(image.at(k).r) * image.at(k).r;
  // Sample std σ_h exactly in double; the file holds float32 (relative rounding 6e-8).
  EXPECT_NEAR(std::sqrt(sum2 / double(image.pixel_count())), 0.2, 1e-6);
  EXPECT_EQ(std::get<double>(m.at("facet:sigma_h")), 0.2);
  EXPECT_EQ(std::get<double>(m.at("facet:texel_size")), 0.5);
  EXPECT_EQ(std::get<double>(m.at("facet:angle_deg")), 20.0);
  EXPECT_EQ(std::get<std::string>(m.at("facet:seed")), "9");
  EXPECT_GT(std::get<double>(m.at("facet:slope_var_x")), 0.0);
  EXPECT_TRUE(m.count("facet:sample_slope_var_y"));

  ASSERT_EQ(facet("make heightfield -o " + out("b.exr") +
                  " --width 64 --height 48 --texel-size 0.5 --sigma-h 0.2 "
                  "--corr-x 3 --corr-y 2 --angle-deg 20 --seed 9")
                .exit_code,
            0);
  EXPECT_EQ(bytes(out("a.exr")), bytes(out("b.exr")));
}

TEST_F(MakeCommand, NoiseSpansZeroToOne) {
  auto r = facet("make noise -o " + out("n.exr") + " --size 32 --octaves 3 --gain 0.6 --base-frequency 2 --seed 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata m;
  Image image = read_exr(out("n.exr"), &m);
  auto [lo, hi] = std::minmax_element(image.rgb.begin(), image.rgb.end());
  EXPECT_EQ(*lo, 0.0f);
  EXPECT_EQ(*hi, 1.0f);
  EXPECT_EQ(std::get<std::int64_t>(m.at("facet:octaves")), 3);
  EXPECT_EQ(std::get<std::string>(m.at("facet:generator")), "fbm_gradient_noise");
}

TEST_F(MakeCommand, BadParametersFailWithOneLine) {
  for (std::string args : {"make heightfield --size 64 --corr-x 40", "make heightfield --size 64 --sigma-h -1",
                           "make noise --size 16 --gain 2", "make noise --size 0"}) {
    auto r = facet(args + " -o " + out("bad.exr"));
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("facet: error: "), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out("bad.exr"))) << args;
  }
}

}  // namespace
}  // namespace facet
