// Faults from outside, end to end through the `facet` program: each gives a non-zero exit and exactly
// one "facet: error: ..." line, and leaves no output and no temporary file behind (docs/hardening.md).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

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
  const auto r = run_command(kFacet + " render " + kDefaultScene + " -o " + (dir_ / "blocker" / "out.exr").string() +
                             " --width 16 --height 9");
  fs::remove(dir_ / "blocker");
  expect_clean_failure(r, "blocker");
}

TEST_F(Faults, FullDiskViaFileSizeLimit) {
  // ulimit -f counts 512-byte blocks in dash: the EXR (tens of kB) cannot be written. facet ignores
  // SIGXFSZ, so the write fails with EFBIG instead of the process being killed.
  const auto r = run_command("ulimit -f 4; " + kFacet + " render " + kDefaultScene + " -o " + out() +
                             " --width 128 --height 72 --pixel-type float");
  expect_clean_failure(r, "out.exr");
}

TEST_F(Faults, SigintDuringRender) {
  const auto r =
      interrupted(kFacet + " render " + kDefaultScene + " -o " + out() + " --width 8192 --height 8192", "INT", 2);
  EXPECT_EQ(r.exit_code, 130) << "still running after 2 s? " << r.err;
  expect_clean_failure(r, "interrupted by SIGINT");
}

TEST_F(Faults, SigtermDuringRender) {
  const auto r =
      interrupted(kFacet + " render " + kDefaultScene + " -o " + out() + " --width 8192 --height 8192", "TERM", 2);
  EXPECT_EQ(r.exit_code, 143) << r.err;
  expect_clean_failure(r, "SIGTERM");
}

TEST_F(Faults, SigintAndSigtermDuringReference) {
  for (const std::string signal : {"INT", "TERM"}) {
    const auto r = interrupted(
        kFacet + " reference " + kDefaultScene + " -o " + out() + " --width 1024 --height 576 --grid 32 --threads 2",
        signal, 2);
    EXPECT_EQ(r.exit_code, signal == "INT" ? 130 : 143) << r.err;  // the same statuses as `render`
    expect_clean_failure(r, "interrupt");
  }
}

TEST_F(Faults, NoVulkanDevice) {
  const std::string no_driver = "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json ";
  expect_clean_failure(
      run_command(no_driver + kFacet + " render " + kDefaultScene + " -o " + out() + " --width 16 --height 9"),
      "Vulkan");
  expect_clean_failure(
      run_command(kFacet + " render " + kDefaultScene + " -o " + out() + " --width 16 --height 9 --device nosuch"),
      "nosuch");
}

TEST_F(Faults, AbsurdSizesAreRefusedBeforeAllocation) {
  // Each would need tens of GB to hundreds of TB; refused by the documented bounds (docs/limits.md).
  for (const std::string& args :
       {" render " + kDefaultScene + " -o " + out() + " --width 100000 --height 100000",
        " render " + kDefaultScene + " -o " + out() + " --width -5",
        " reference " + kDefaultScene + " -o " + out() + " --grid 100000",
        " make heightfield -o " + out() + " --size 100000", " make noise -o " + out() + " --width 3000000000",
        " make noise -o " + out() + " --size 65536"})
    expect_clean_failure(run_command(kFacet + args), "");
}

TEST_F(Faults, FramesBeyondTheStorageBufferRangeRenderWhole) {
  // 2900^2 RGBA32F pixels are 134.56 MB, beyond lavapipe's 128 MiB (134.22 MB) storage-buffer range:
  // the frame must render whole (tile by tile), not fail or leave tiles black. A 290^2 render with
  // ss:10 traces the same rays (small pixel x, sample s: film (x + (s + 0.5) / 10) / 290 = (10 x + s +
  // 0.5) / 2900), so each 10x10 block of the large frame averages to its small pixel up to float
  // rounding of the ray directions and of the sums (a rare edge pixel may flip). Pooled over 29x29-pixel
  // regions of the small frame the worst mean difference measured 3.5e-7; a black or misplaced tile
  // would shift its region's mean by its radiance (>= 0.05). Tolerance 1e-4: a few flipped edges.
  const fs::path large = dir_ / "large.exr", small = dir_ / "small.exr";
  for (const auto& [file, size] : {std::pair{large, " --width 2900 --height 2900"},
                                   std::pair{small, " --width 290 --height 290 --method ss:10"}}) {
    const auto r = run_command(kFacet + " render " + kDefaultScene + " -o " + file.string() + size +
                               " --pixel-type float --no-preview");
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  const Image big = read_exr(large), reference = read_exr(small);
  ASSERT_EQ(big.width, 2900);
  ASSERT_EQ(big.height, 2900);
  double worst = 0.0;
  for (int ry = 0; ry < 10; ++ry)
    for (int rx = 0; rx < 10; ++rx) {
      double difference = 0.0;
      for (int y = 29 * ry; y < 29 * (ry + 1); ++y)
        for (int x = 29 * rx; x < 29 * (rx + 1); ++x) {
          glm::dvec3 block(0.0);
          for (int j = 0; j < 10; ++j)
            for (int i = 0; i < 10; ++i) block += glm::dvec3(big.at(10 * x + i, 10 * y + j));
          const glm::dvec3 d = block / 100.0 - glm::dvec3(reference.at(x, y));
          difference += (std::abs(d.x) + std::abs(d.y) + std::abs(d.z)) / 3.0;
        }
      worst = std::max(worst, difference / (29.0 * 29.0));
    }
  EXPECT_LT(worst, 1e-4) << "a region of the large frame differs from the same rays rendered small";
}

}  // namespace
}  // namespace facet
