// What `facet` prints agrees with what it counts and measures: "1 tile", "1 Vulkan device", no device
// time on a CPU reference frame.
#include <filesystem>
#include <regex>
#include <string>

#include <gtest/gtest.h>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

class CliWording : public ::testing::Test {
 protected:
  test::TempDir dir_;
};

TEST_F(CliWording, OneTileIsOneTile) {
  // 16x16 fits one 256-pixel tile.
  const auto r = run_command(kFacet + " render " + kDefaultScene + " -o " + (dir_ / "f.exr").string() +
                             " --width 16 --height 16 --no-preview");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(" ms in 1 tile) on "), std::string::npos) << r.err;
}

TEST_F(CliWording, DeviceCountAgreesWithItsNoun) {
  const auto r = run_command(kFacet + " render " + kDefaultScene + " -o " + (dir_ / "f.exr").string() + " --device 99");
  EXPECT_NE(r.exit_code, 0);
  std::smatch count;
  ASSERT_TRUE(std::regex_search(r.err, count, std::regex("has ([0-9]+) Vulkan device(s?) \\(see 'facet info'\\)")))
      << r.err;
  EXPECT_EQ(count[1] == "1", count[2].length() == 0) << r.err;
}

TEST_F(CliWording, OneOctaveIsOneOctave) {
  const auto r = run_command(kFacet + " make noise --size 8 --octaves 1 -o " + (dir_ / "n.exr").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(", 1 octave -> "), std::string::npos) << r.err;
}

TEST_F(CliWording, ReferenceFramesCarryNoDeviceTime) {
  const fs::path out = dir_ / "ref.exr";
  const auto r =
      run_command(kFacet + " reference " + kDefaultScene + " -o " + out.string() + " --width 8 --height 8 --grid 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata metadata;
  read_exr(out, &metadata);
  EXPECT_EQ(metadata.count("facet:gpu_ms"), 0u);
  EXPECT_GT(std::get<double>(metadata.at("facet:render_ms")), 0.0);
}

}  // namespace
}  // namespace facet
