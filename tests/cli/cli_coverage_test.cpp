// The A channel of every frame is coverage, the fraction of a pixel's samples that hit geometry: 0 on
// the background, 1 inside a silhouette, between at its edge, in the GPU render (ss:K strata) and the
// CPU reference (jittered rays) alike; `facet compare` reads frames with or without it.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

// A unit ball 5 units in front of the camera, centred in a 32 x 32 frame with a 90° field of view:
// its silhouette is the circle of radius 16 tan(asin(1/5)) = 3.266 pixels about the frame's centre.
const std::string kCoverageScene = R"({
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 90, "width": 32, "height": 32},
  "background": [0.2, 0.3, 0.4],
  "materials": {"grey": {"type": "lambert"}},
  "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "grey"}]
})";
const double kSilhouetteRadius = 16.0 * std::tan(std::asin(0.2));

class CliCoverage : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_ / "ball.json") << kCoverageScene; }
  ScalarImage render(const std::string& command, const std::string& options, const std::string& name) {
    const auto r = run_command(kFacet + " " + command + " " + (dir_ / "ball.json").string() + " --no-preview -o " +
                               (dir_ / name).string() + " " + options);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_exr_scalar(dir_ / name, "A");
  }
  // Background corner 0, the centre 1, a pixel the silhouette crosses strictly between, and the
  // coverage summed over the frame the circle's area in pixels.
  static void expect_coverage_of_the_ball(const ScalarImage& a) {
    ASSERT_EQ(a.width, 32);
    EXPECT_EQ(a.at(0, 0), 0.0f);
    EXPECT_EQ(a.at(31, 31), 0.0f);
    EXPECT_EQ(a.at(15, 15), 1.0f);
    EXPECT_EQ(a.at(16, 16), 1.0f);
    // Pixel (19, 16) spans 3..4 pixels right of the centre and 0..1 below it: the circle leaves it at ~3.23.
    EXPECT_GT(a.at(19, 16), 0.0f);
    EXPECT_LT(a.at(19, 16), 1.0f);
    const double area = std::accumulate(a.values.begin(), a.values.end(), 0.0);
    EXPECT_NEAR(area, M_PI * kSilhouetteRadius * kSilhouetteRadius, 0.03 * area);
  }
  test::TempDir dir_;
};

TEST_F(CliCoverage, GpuAndReferenceCoverageIsTheBallsSilhouetteAndTheyAgree) {
  const ScalarImage gpu = render("render", "--method ss:4", "gpu.exr");
  const ScalarImage reference = render("reference", "--grid 8", "reference.exr");
  expect_coverage_of_the_ball(gpu);
  expect_coverage_of_the_ball(reference);
  // 16 strata against 64 jittered rays: an edge pixel's two estimates differ by a few strata at most.
  for (std::size_t i = 0; i < gpu.values.size(); ++i)
    EXPECT_NEAR(gpu.values[i], reference.values[i], 0.3) << "pixel " << i % 32 << ", " << i / 32;

  // compare measures RGB: the same numbers whether the reference has an A channel or not.
  const auto with_alpha = run_command(kFacet + " compare " + (dir_ / "gpu.exr").string() + " " +
                                      (dir_ / "reference.exr").string() + " --json");
  ASSERT_EQ(with_alpha.exit_code, 0) << with_alpha.err;
  write_exr(dir_ / "rgb_only.exr", read_exr(dir_ / "reference.exr"), {}, ExrPixelType::Half);
  EXPECT_THROW(read_exr_scalar(dir_ / "rgb_only.exr", "A"), Error);
  const auto without_alpha = run_command(kFacet + " compare " + (dir_ / "gpu.exr").string() + " " +
                                         (dir_ / "rgb_only.exr").string() + " --json");
  ASSERT_EQ(without_alpha.exit_code, 0) << without_alpha.err;
  EXPECT_EQ(with_alpha.out, without_alpha.out);
}

}  // namespace
}  // namespace facet
