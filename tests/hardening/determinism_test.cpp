// Determinism (docs/hardening.md): a reference is bit-identical across thread counts and runs; a GPU
// render is bit-identical across runs on the same device. Pixels are compared as bytes, so even a
// differently signed zero or a NaN payload would count as a difference.
#include <cstring>
#include <filesystem>
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

class Determinism : public ::testing::Test {
 protected:
  Image run(const std::string& arguments, const std::string& name) {
    const fs::path out = dir_ / (name + ".exr");
    const auto r = run_command(kFacet + " " + arguments + " -o " + out.string() + " --pixel-type float --no-preview");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_exr(out);
  }

  static bool identical(const Image& a, const Image& b) {
    return a.width == b.width && a.height == b.height && a.rgb.size() == b.rgb.size() &&
           std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
  }

  test::TempDir dir_;
};

TEST_F(Determinism, ReferenceIsBitIdenticalAcrossThreadCountsAndRuns) {
  // The microsurface scene exercises the traced height field as well as the Embree meshes.
  for (const std::string scene : {"default.json", "microsurface_terrain.json"}) {
    const std::string args = "reference " + (kScenes / scene).string() + " --width 24 --height 16 --grid 3 --seed 9";
    const Image one = run(args + " --threads 1", "one");
    const Image two = run(args + " --threads 2", "two");
    const Image again = run(args + " --threads 2", "again");
    ASSERT_GT(one.width, 0);
    EXPECT_TRUE(identical(one, two)) << scene;
    EXPECT_TRUE(identical(two, again)) << scene;
  }
}

TEST_F(Determinism, GpuRenderIsBitIdenticalAcrossRuns) {
  for (const std::string method : {"naive", "filtered"}) {
    const std::string args =
        "render " + (kScenes / "colormap_noise_plane.json").string() + " --width 96 --height 54 --method " + method;
    const Image first = run(args, "first");
    const Image second = run(args, "second");
    ASSERT_GT(first.width, 0);
    EXPECT_TRUE(identical(first, second)) << method;
  }
}

}  // namespace
}  // namespace facet
