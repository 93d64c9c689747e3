// `facet render --method filtered:adaptive[:K]` with its budget options: refused combinations in one
// line, the refined pixel count in the frame's metadata, and a budget that changes what is refined.
#include <string>

#include <gtest/gtest.h>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace cli_adaptive_test {

using test::run_command;

class CliAdaptive : public ::testing::Test {
 protected:
  test::CommandResult render(const std::string& scene, const std::string& options) {
    return run_command(kFacet + " render " + (kScenes / scene).string() + " -o " + out().string() +
                       " --width 48 --no-preview " + options);
  }
  std::filesystem::path out() const { return dir_ / "f.exr"; }
  std::int64_t refined_pixels() const {
    ExrMetadata metadata;
    read_exr(out(), &metadata);
    const auto at = metadata.find("facet:refined_pixels");
    return at == metadata.end() ? -1 : std::get<std::int64_t>(at->second);
  }
  test::TempDir dir_;
};

TEST_F(CliAdaptive, BadMethodsAndBudgetsAreRefusedInOneLine) {
  for (const std::string options :
       {"--method filtered --adaptive-error 0.01", "--method ss:4 --adaptive-time 100", "--method filtered:adaptive:1",
        "--method filtered:adaptive:17", "--method filtered:adaptivex",
        "--method filtered:adaptive --adaptive-error -1", "--method filtered:adaptive --adaptive-time 0"}) {
    const auto r = render("colormap_objects.json", options);
    EXPECT_NE(r.exit_code, 0) << options;
    EXPECT_EQ(r.err.rfind("facet: error: ", 0), 0u) << options << ": " << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << options << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(out())) << options;
  }
}

TEST_F(CliAdaptive, TheFrameSaysHowManyPixelsWereRefined) {
  // 48 x 27 = 1296 pixels; the default budget is 4 n units of work (gpu/adaptive_refinement.hpp). On the
  // noise plane every estimated pixel is textured, and the cheapest refined textured pixel (K = 2) costs 20:
  // at most n / 5 = 259 pixels, and exactly that many with K = 2 alone (filtered:adaptive:2).
  auto r = render("colormap_noise_plane.json", "--method filtered:adaptive");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::int64_t by_default = refined_pixels();
  EXPECT_GT(by_default, 0);
  EXPECT_LE(by_default, 259);
  r = render("colormap_noise_plane.json", "--method filtered:adaptive:2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(refined_pixels(), 259);
  // An error budget above every estimate refines nothing.
  r = render("colormap_objects.json", "--method filtered:adaptive --adaptive-error 1e6");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(refined_pixels(), 0);
  // Other methods do not carry the key.
  r = render("colormap_objects.json", "--method filtered");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(refined_pixels(), -1);
}

}  // namespace cli_adaptive_test
}  // namespace facet
