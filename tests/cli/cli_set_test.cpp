// `--set PATH=VALUE` through the built executable: overrides of scene keys change the frame (its size,
// a nested and an array element's value), are recorded as facet:set, and a path that names nothing
// fails in one line before anything is written.
#include <algorithm>
#include <filesystem>
#include <fstream>
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

// Looking down -z at a ball of radius 0.1 at the origin, lit from the camera, on black. With a
// 90° field of view the 16-pixel image plane spans [-5, 5] at the ball, so the rays through the
// centres of the four middle pixels pass 0.3125 from the axis: they miss it until it grows.
const std::string kSetScene = R"({
  "camera": {"position": [0, 0, 5], "target": [0, 0, 0], "fov_y": 90, "width": 16, "height": 16},
  "light": {"direction": [0, 0, 1], "irradiance": [1, 1, 1]},
  "materials": {"grey": {"type": "lambert", "albedo": [0.8, 0.8, 0.8]}},
  "objects": [{"type": "sphere", "center": [3, 3, 0], "radius": 0.5, "material": "grey"},
              {"type": "sphere", "center": [0, 0, 0], "radius": 0.1, "material": "grey"}]
})";

class CliSet : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_ / "scene.json") << kSetScene; }
  // `facet reference` with one ray per pixel centre (no Vulkan: fast), float pixels.
  test::CommandResult reference(const std::string& sets, const std::string& name = "out.exr") {
    return run_command(kFacet + " reference " + (dir_ / "scene.json").string() + " --grid 1 --no-preview " +
                       "--pixel-type float -o " + (dir_ / name).string() + " " + sets);
  }
  test::TempDir dir_;
};

TEST_F(CliSet, AnOverrideChangesTheFrameSizeOnTheGpuAndIsRecorded) {
  const auto r = run_command(kFacet + " render " + (dir_ / "scene.json").string() +
                             " --set camera.width=24 --set camera.height=12 --no-preview -o " +
                             (dir_ / "gpu.exr").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata metadata;
  const Image image = read_exr(dir_ / "gpu.exr", &metadata);
  EXPECT_EQ(image.width, 24);
  EXPECT_EQ(image.height, 12);
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:set")), R"(["camera.width=24","camera.height=12"])");
}

TEST_F(CliSet, NestedAndArrayOverridesTakeEffect) {
  ASSERT_EQ(reference("", "plain.exr").exit_code, 0);
  const auto grown = reference("--set objects.1.radius=1", "grown.exr");
  ASSERT_EQ(grown.exit_code, 0) << grown.err;
  const auto darker = reference("--set objects.1.radius=1 --set 'materials.grey.albedo=[0.4, 0.4, 0.4]'", "dark.exr");
  ASSERT_EQ(darker.exit_code, 0) << darker.err;
  const float plain = read_exr(dir_ / "plain.exr").at(8, 8).g;
  const float bright = read_exr(dir_ / "grown.exr").at(8, 8).g;
  const float dark = read_exr(dir_ / "dark.exr").at(8, 8).g;
  EXPECT_EQ(plain, 0.0f);  // the small ball is missed
  EXPECT_GT(bright, 0.1f);
  EXPECT_NEAR(dark / bright, 0.5f, 1e-6f);  // Lambertian radiance is linear in the albedo
  ExrMetadata metadata;
  read_exr(dir_ / "dark.exr", &metadata);
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:set")),
            R"(["objects.1.radius=1","materials.grey.albedo=[0.4, 0.4, 0.4]"])");
  EXPECT_EQ(read_exr(dir_ / "plain.exr", &metadata).width, 16);
  EXPECT_EQ(metadata.count("facet:set"), 0u);  // no overrides, no attribute
}

TEST_F(CliSet, APathThatNamesNothingFailsInOneLineNamingTheNearestKey) {
  const auto typo = reference("--set camra.width=24");
  EXPECT_NE(typo.exit_code, 0);
  EXPECT_EQ(typo.err, "facet: error: --set camra.width=24: \"camra\" names nothing in " +
                          (dir_ / "scene.json").string() + " (did you mean \"camera\"?)\n");
  const auto index = reference("--set objects.2.radius=1");
  EXPECT_NE(index.exit_code, 0);
  EXPECT_EQ(index.err, "facet: error: --set objects.2.radius=1: \"2\" names nothing: objects in " +
                           (dir_ / "scene.json").string() + " is an array of 2 (indices from 0)\n");
  // A new last key is the scene format's to judge: its own check names the nearest known key.
  const auto leaf = reference("--set camera.widht=24");
  EXPECT_NE(leaf.exit_code, 0);
  EXPECT_NE(leaf.err.find("unknown key \"widht\" in camera (did you mean \"width\"?"), std::string::npos) << leaf.err;
  // So do its type and range checks.
  const auto range = reference("--set camera.width=-4");
  EXPECT_NE(range.err.find("camera.width must be an integer in [1, 16384], got -4"), std::string::npos) << range.err;
  for (const auto* result : {&typo, &index, &leaf, &range})
    EXPECT_EQ(std::count(result->err.begin(), result->err.end(), '\n'), 1) << result->err;
  EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

}  // namespace
}  // namespace facet
