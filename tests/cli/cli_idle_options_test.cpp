// Options of `facet render` that the scene gives nothing to act on are said so in one warning line,
// and the frame still renders.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

class CliIdleOptions : public ::testing::Test {
 protected:
  test::CommandResult render(const std::string& scene, const std::string& options) {
    return run_command(kFacet + " render " + (kScenes / scene).string() + " -o " + (dir_ / "f.exr").string() +
                       " --width 16 --height 16 --no-preview " + options);
  }
  static long warnings(const test::CommandResult& r) {
    long count = 0;
    for (std::size_t at = r.err.find("facet: warning: "); at != std::string::npos;
         at = r.err.find("facet: warning: ", at + 1))
      ++count;
    return count;
  }
  // Renders `scene` with `options`: it succeeds with `count` warnings.
  void expect_warnings(const std::string& scene, const std::string& options, long count) {
    const auto r = render(scene, options);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(warnings(r), count) << scene << " " << options << ": " << r.err;
  }
  test::TempDir dir_;
};

TEST_F(CliIdleOptions, AFootprintMethodWithoutSubPixelDetailIsSaidToDoNothing) {
  for (const std::string method : {"filtered", "mip", "colormip", "filtered:table", "filtered:ss:2"}) {
    const auto r = render("default.json", "--method " + method);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(warnings(r), 1) << r.err;
    const bool filters = method.rfind("filtered", 0) == 0;
    EXPECT_NE(r.err.find(std::string("has no colormap_texture or microsurface material") +
                         (filters ? " (nor microflake, nor a grating rendered by orders)" : "") + ": --method " +
                         method + " renders it as"),
              std::string::npos)
        << r.err;
  }
  expect_warnings("colormap_noise_plane.json", "--method filtered", 0);
  // filtered averages microflake lobes over the pixel; mip leaves them at its centre
  expect_warnings("microflake_blend.json", "--method filtered", 0);
  expect_warnings("microflake_blend.json", "--method mip", 1);
  // filtered averages the orders of a grating rendered by `orders` over the pixel, not the spectral path's
  expect_warnings("diffraction_spheres.json", "--method filtered", 0);
  expect_warnings("diffraction_spheres.json", "--method filtered --diffraction spectral", 1);
  expect_warnings("diffraction_plate.json", "--method filtered --diffraction orders", 0);
}

TEST_F(CliIdleOptions, DiffractionOptionsWithoutADiffractionMaterialAreSaidToDoNothing) {
  const auto r = render("default.json", "--diffraction orders --wavelengths 16 --taylor 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(warnings(r), 1) << r.err;
  EXPECT_NE(r.err.find("has no diffraction material: --diffraction orders, --wavelengths 16, --taylor 4 do nothing"),
            std::string::npos)
      << r.err;
  const auto method = render("default.json", "--method diffraction:preintegrated");
  ASSERT_EQ(method.exit_code, 0) << method.err;
  EXPECT_NE(method.err.find("--method diffraction:preintegrated does nothing"), std::string::npos) << method.err;
  EXPECT_EQ(warnings(render("default.json", "")), 0);
}

}  // namespace
}  // namespace facet
