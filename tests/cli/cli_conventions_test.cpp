// What users' tools expect of any command line: --version, "did you mean", one side of the
// resolution keeping the aspect, output folders created and output names that say what they hold.
#include <algorithm>
#include <filesystem>

#include <gtest/gtest.h>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;

class CliConventions : public ::testing::Test {
 protected:
  test::CommandResult facet(const std::string& args) { return test::run_command(kFacet + " " + args); }
  std::string out(const std::string& name) { return (dir_ / name).string(); }
  // Non-zero exit and one line on stderr containing `needle`.
  static void expect_one_line_error(const test::CommandResult& r, const std::string& needle) {
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("facet: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  }
  test::TempDir dir_;
};

TEST_F(CliConventions, VersionPrintsTheBuildsVersion) {
  auto r = facet("--version");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, std::string("facet ") + FACET_VERSION + "\n");
}

TEST_F(CliConventions, MistypedCommandsAndOptionsNameTheNearestValidOne) {
  expect_one_line_error(facet("rendr"), "unknown command 'rendr'; did you mean 'render'?");
  expect_one_line_error(facet("make nois -o " + out("n.exr")), "did you mean 'noise'?");
  expect_one_line_error(facet("render " + kDefaultScene + " -o " + out("a.exr") + " --widht 16"),
                        "unknown option '--widht'; did you mean '--width'?");
  expect_one_line_error(facet("compare a.exr b.exr --jsn"), "did you mean '--json'?");
  // Nothing near: CLI11's own message, still one line.
  expect_one_line_error(facet("render " + kDefaultScene + " -o " + out("a.exr") + " --zzzzzzzz"), "zzzzzzzz");
}

TEST_F(CliConventions, OneSideOfTheResolutionKeepsTheScenesAspect) {
  auto r = facet("render " + kDefaultScene + " -o " + out("w.exr") + " --width 64 --no-preview");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  Image image = read_exr(out("w.exr"));
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 36);
  r = facet("reference " + kDefaultScene + " -o " + out("h.exr") + " --height 9 --grid 1 --no-preview");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  image = read_exr(out("h.exr"));
  EXPECT_EQ(image.width, 16);
  EXPECT_EQ(image.height, 9);
}

TEST_F(CliConventions, OutputFoldersAreCreated) {
  auto r = facet("make noise --size 8 -o " + out("made/deep/n.exr"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "made" / "deep" / "n.exr"));
  r = facet("compare " + out("made/deep/n.exr") + " " + out("made/deep/n.exr") + " --heatmap " + out("maps/sub/h.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "maps" / "sub" / "h.png"));
}

TEST_F(CliConventions, OutputNamesMustSayWhatTheFileHolds) {
  expect_one_line_error(facet("make noise --size 8 -o " + out("n.png")), "n.png would hold OpenEXR data");
  expect_one_line_error(facet("make heightfield --size 8 -o " + out("h.tif")), ".exr");
  expect_one_line_error(facet("render " + kDefaultScene + " -o " + out("r.png")), "r.png would hold OpenEXR data");
  expect_one_line_error(facet("reference " + kDefaultScene + " -o " + out("r.png")), "r.png");
  expect_one_line_error(facet("compare a.exr b.exr --heatmap " + out("m.exr")), "m.exr would hold PNG data");
  EXPECT_TRUE(fs::is_empty(dir_.path())) << "nothing written";
}

}  // namespace
}  // namespace facet
