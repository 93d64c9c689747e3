// Faults from outside, end to end through the `facet` program: each gives a non-zero exit and exactly
// one "facet: error: ..." line, and leaves no output and no temporary file behind (docs/hardening.md).
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "image/temp_dir.hpp"
#include "support/run_command.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

const std::string kFacet = FACET_EXECUTABLE;
const std::string kScene = (fs::path(FACET_SOURCE_DIR) / "scenes" / "default.json").string();

int error_lines(const std::string& err) {
  int count = 0;
  for (std::size_t at = err.find("facet: error: "); at != std::string::npos; at = err.find("facet: error: ", at + 1))
    ++count;
  return count;
}

class Faults : public ::testing::Test {
 protected:
  std::string out() const { return (dir_ / "out.exr").string(); }

  // Non-zero exit, one error line naming `needle`, and nothing written into the folder (no EXR, no
  // PNG preview, no hidden temporary).
  void expect_clean_failure(const test::CommandResult& r, const std::string& needle) {
    EXPECT_NE(r.exit_code, 0) << r.err;
    EXPECT_EQ(error_lines(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    EXPECT_EQ(r.err.back(), '\n') << r.err;
    EXPECT_TRUE(fs::is_empty(dir_.path())) << "left behind: " << fs::directory_iterator(dir_.path())->path();
  }

  // Starts `command` in the background, sends `signal` after `seconds`, and waits for it.
  test::CommandResult interrupted(const std::string& command, const std::string& signal, double seconds) {
    return run_command(command + " & pid=$!; sleep " + std::to_string(seconds) + "; kill -" + signal +
                       " $pid; wait $pid");
  }

  test::TempDir dir_;
};

TEST_F(Faults, OutputFolderThatCannotBeCreated) {
  // A regular file where the output folder should be: fails for root too, unlike permissions.
  std::ofstream(dir_ / "blocker") << "not a folder";
  const auto r = run_command(kFacet + " render " + kScene + " -o " + (dir_ / "blocker" / "out.exr").string() +
                             " --width 16 --height 9");
  fs::remove(dir_ / "blocker");
  expect_clean_failure(r, "blocker");
}

TEST_F(Faults, FullDiskViaFileSizeLimit) {
  // ulimit -f counts 512-byte blocks in dash: the EXR (tens of kB) cannot be written. facet ignores
  // SIGXFSZ, so the write fails with EFBIG instead of the process being killed.
  const auto r = run_command("ulimit -f 4; " + kFacet + " render " + kScene + " -o " + out() +
                             " --width 128 --height 72 --pixel-type float");
  expect_clean_failure(r, "out.exr");
}

TEST_F(Faults, SigintDuringRender) {
  const auto r = interrupted(kFacet + " render " + kScene + " -o " + out() + " --width 8192 --height 8192", "INT", 2);
  EXPECT_EQ(r.exit_code, 130) << "still running after 2 s? " << r.err;
  expect_clean_failure(r, "interrupted by SIGINT");
}

TEST_F(Faults, SigtermDuringRender) {
  const auto r = interrupted(kFacet + " render " + kScene + " -o " + out() + " --width 8192 --height 8192", "TERM", 2);
  EXPECT_EQ(r.exit_code, 143) << r.err;
  expect_clean_failure(r, "SIGTERM");
}

TEST_F(Faults, SigintAndSigtermDuringReference) {
  for (const std::string signal : {"INT", "TERM"}) {
    const auto r = interrupted(kFacet + " reference " + kScene + " -o " + out() +
                                   " --width 1024 --height 576 --grid 32 --threads 2",
                               signal, 2);
    expect_clean_failure(r, "interrupt");
  }
}

TEST_F(Faults, NoVulkanDevice) {
  const std::string no_driver = "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json ";
  expect_clean_failure(run_command(no_driver + kFacet + " render " + kScene + " -o " + out() + " --width 16 --height 9"),
                       "Vulkan");
  expect_clean_failure(
      run_command(kFacet + " render " + kScene + " -o " + out() + " --width 16 --height 9 --device nosuch"), "nosuch");
}

TEST_F(Faults, AbsurdSizesAreRefusedBeforeAllocation) {
  // Each would need tens of GB to hundreds of TB; refused by the documented bounds (docs/limits.md).
  for (const std::string& args : {" render " + kScene + " -o " + out() + " --width 100000 --height 100000",
                                 " render " + kScene + " -o " + out() + " --width -5",
                                 " reference " + kScene + " -o " + out() + " --grid 100000",
                                 " make heightfield -o " + out() + " --size 100000",
                                 " make noise -o " + out() + " --width 3000000000",
                                 " make noise -o " + out() + " --size 65536"})
    expect_clean_failure(run_command(kFacet + args), "");
}

}  // namespace
}  // namespace facet
