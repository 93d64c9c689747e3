// The `facet` program end to end: what a user sees on good and bad input.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace {

namespace fs = std::filesystem;
using test::run_command;

class Cli : public ::testing::Test {
 protected:
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name) << text;
    return dir_ / name;
  }
  // A failed command: non-zero exit, exactly one line on stderr, naming `needle`, and no EXR.
  void expect_clean_failure(const test::CommandResult& r, const std::string& needle) {
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find("facet: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
  }
  test::TempDir dir_;
};

TEST_F(Cli, RendersTheDefaultSceneToExrAndPng) {
  auto out = dir_ / "sub" / "default.exr";
  auto r = run_command(kFacet + " render " + (kScenes / "default.json").string() + " -o " + out.string() +
                       " --width 64 --height 36 --validation");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata metadata;
  Image image = read_exr(out, &metadata);
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 36);
  EXPECT_TRUE(fs::exists(dir_ / "sub" / "default.png"));
  EXPECT_EQ(std::get<std::string>(metadata.at("facet:method")), "naive");
  EXPECT_EQ(std::get<std::int64_t>(metadata.at("facet:spp")), 1);
  EXPECT_NE(std::get<std::string>(metadata.at("facet:device")).find("llvmpipe"), std::string::npos);
  EXPECT_GT(std::get<double>(metadata.at("facet:render_ms")), 0.0);
  // Not a blank frame: the scene has lit and shadowed surfaces.
  float lo = *std::min_element(image.rgb.begin(), image.rgb.end());
  float hi = *std::max_element(image.rgb.begin(), image.rgb.end());
  EXPECT_LT(lo, hi);
  // A third-party reader sees the same file and its metadata.
  auto info = run_command("oiiotool --info -v " + out.string());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find(":   64 x   36, 4 channel"), std::string::npos) << info.out;  // R, G, B, A (coverage)
  EXPECT_NE(info.out.find("facet:method: \"naive\""), std::string::npos) << info.out;
}

// --timings prints each phase; the EXR carries them, and together they account for the frame's wall clock.
TEST_F(Cli, TimingsNameEveryPhaseAndAccountForTheWallClock) {
  auto out = dir_ / "t.exr";
  auto r = run_command(kFacet + " render " + (kScenes / "colormap_noise_plane.json").string() + " -o " + out.string() +
                       " --width 32 --method filtered --timings --no-preview");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ExrMetadata metadata;
  read_exr(out, &metadata);
  double phases_ms = 0.0;
  for (const char* phase : {"load", "device", "upload", "diffraction", "pipeline", "jit", "render"}) {
    EXPECT_NE(r.err.find("  " + std::string(phase) + " "), std::string::npos) << phase << " in " << r.err;
    const double ms = std::get<double>(metadata.at("facet:phase:" + std::string(phase) + "_ms"));
    EXPECT_GE(ms, 0.0) << phase;
    phases_ms += ms;
  }
  EXPECT_NE(r.err.find("  write "), std::string::npos) << r.err;  // printed, not in the file it times
  const double wall_ms = std::get<double>(metadata.at("facet:render_ms"));
  EXPECT_GE(phases_ms, 0.9 * wall_ms);
  EXPECT_LE(phases_ms, 1.01 * wall_ms + 1.0);
}

TEST_F(Cli, MalformedJsonIsOneLineError) {
  auto scene = write("bad.json", "{ \"camera\": { \"width\": 4, ");
  expect_clean_failure(run_command(kFacet + " render " + scene.string() + " -o " + (dir_ / "out.exr").string()),
                       "bad.json");
}

TEST_F(Cli, MissingSceneFileIsOneLineError) {
  expect_clean_failure(
      run_command(kFacet + " render " + (dir_ / "nope.json").string() + " -o " + (dir_ / "out.exr").string()),
      "nope.json");
}

TEST_F(Cli, MissingMeshFileIsOneLineError) {
  auto scene = write("mesh.json", R"({"camera": {"width": 8, "height": 8},
    "materials": {"m": {"type": "lambert", "albedo": [0.5, 0.5, 0.5]}},
    "objects": [{"type": "mesh", "file": "missing.gltf", "material": "m"}]})");
  expect_clean_failure(run_command(kFacet + " render " + scene.string() + " -o " + (dir_ / "out.exr").string()),
                       "missing.gltf");
}

TEST_F(Cli, UnknownMaterialTypeIsOneLineError) {
  auto scene = write("mat.json", R"({"camera": {"width": 8, "height": 8},
    "materials": {"m": {"type": "velvet"}},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})");
  expect_clean_failure(run_command(kFacet + " render " + scene.string() + " -o " + (dir_ / "out.exr").string()),
                       "velvet");
}

TEST_F(Cli, NegativeResolutionIsOneLineError) {
  auto scene = write("neg.json", R"({"camera": {"width": -4, "height": 8}})");
  expect_clean_failure(run_command(kFacet + " render " + scene.string() + " -o " + (dir_ / "out.exr").string()),
                       "width");
}

TEST_F(Cli, AbsurdResolutionOverrideIsRefused) {
  auto r = run_command(kFacet + " render " + (kScenes / "default.json").string() + " -o " +
                       (dir_ / "out.exr").string() + " --width 1000000");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
}

TEST_F(Cli, UnknownDeviceIsOneLineError) {
  expect_clean_failure(run_command(kFacet + " render " + (kScenes / "default.json").string() + " -o " +
                                   (dir_ / "out.exr").string() + " --device no-such-device"),
                       "no-such-device");
}

TEST_F(Cli, NoVulkanDeviceIsOneLineError) {
  // Point the loader at a driver manifest that does not exist: no device at all. (Without
  // validation: with it, the loader also reports the missing manifest through the layer.)
  expect_clean_failure(
      run_command(
          "env -u FACET_VALIDATION VK_DRIVER_FILES=/nonexistent/icd.json VK_ICD_FILENAMES=/nonexistent/icd.json " +
          kFacet + " render " + (kScenes / "default.json").string() + " -o " + (dir_ / "out.exr").string()),
      "Vulkan");
}

TEST_F(Cli, InfoListsTheDevice) {
  auto r = run_command(kFacet + " info");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("maxStorageBufferRange"), std::string::npos);
  EXPECT_NE(r.out.find("llvmpipe"), std::string::npos);
}

// --probe adds the measured rates as two more lines, each a finite positive number; without it,
// `facet info` prints what it always did.
TEST_F(Cli, InfoProbeAddsTheMeasuredRates) {
  const auto plain = run_command(kFacet + " info");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("probe_"), std::string::npos) << plain.out;
  const auto r = run_command(kFacet + " info --probe");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.substr(0, plain.out.size()), plain.out);
  for (const std::string key : {"probe_fma_per_second", "probe_texel_reads_per_second"}) {
    const std::size_t at = r.out.find("  " + key + " ");
    ASSERT_NE(at, std::string::npos) << r.out;
    const double rate = std::stod(r.out.substr(at + key.size() + 2));
    EXPECT_TRUE(std::isfinite(rate) && rate > 0.0) << key << " = " << rate;
  }
}

TEST_F(Cli, HelpWorksForEverySubcommand) {
  for (const char* sub : {"", " render", " info"}) {
    auto r = run_command(kFacet + sub + " --help");
    EXPECT_EQ(r.exit_code, 0) << sub;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub;
  }
}

}  // namespace
}  // namespace facet
