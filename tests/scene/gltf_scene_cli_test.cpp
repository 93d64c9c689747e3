// glTF scenes through the built executable: the shipped DCC-like scene renders without a JSON scene
// (`facet render`, and frame by frame along its camera animation in `facet batch`), the same scene
// written as JSON and as glTF renders the same image on the GPU and on the CPU, and a refused file
// is one line on stderr with nothing written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include <tiny_gltf.h>

#include "gltf_test_writer.hpp"
#include "image/exr_io.hpp"
#include "support/facet_paths.hpp"
#include "support/run_command.hpp"
#include "support/temp_dir.hpp"

namespace facet {
namespace gltf_scene_cli_test {

namespace fs = std::filesystem;
using test::run_command;
using Json = nlohmann::json;

const std::string kCourtyard = (kScenes / "gltf_courtyard.gltf").string();

TEST(GltfSceneCli, TheShippedSceneRendersWithoutAJsonScene) {
  test::TempDir dir;
  const auto r =
      run_command(kFacet + " render " + kCourtyard + " --width 48 --no-preview -o " + (dir / "a.exr").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Image image = read_exr(dir / "a.exr");
  EXPECT_EQ(image.width, 48);
  EXPECT_EQ(image.height, 27);  // the camera's aspectRatio 16:9
  // Not only the background (0.55, 0.65, 0.8): the floor, boxes and light are there.
  int background = 0;
  for (size_t i = 0; i < image.rgb.size(); i += 3)
    background += std::abs(image.rgb[i] - 0.55f) < 1e-3f && std::abs(image.rgb[i + 2] - 0.8f) < 1e-3f;
  EXPECT_LT(background, image.width * image.height / 2);

  const auto beyond = run_command(kFacet + " render " + kCourtyard + " --frame 49 -o " + (dir / "x.exr").string());
  EXPECT_NE(beyond.exit_code, 0);
  EXPECT_EQ(beyond.err, "facet: error: " + kCourtyard + ": frame 49 is outside [0, 48]\n");
}

TEST(GltfSceneCli, BatchRendersTheCameraAnimationFrameByFrame) {
  test::TempDir dir;
  std::ofstream(dir / "job.json") << Json({{"scenes", {kCourtyard}},
                                           {"methods", {"naive"}},
                                           {"frames", {0, 48}},
                                           {"output", "out/{frame:02}.exr"},
                                           {"width", 32},
                                           {"height", 18}})
                                         .dump();
  const auto r = run_command(kFacet + " batch " + (dir / "job.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(read_exr(dir / "out/00.exr").rgb, read_exr(dir / "out/48.exr").rgb);  // the camera moved
}

// One scene twice: a glTF file with a camera, a directional light and a quad whose material is
// facet GGX microflakes in extras.facet; and a JSON scene with the same camera, light and material
// written out by hand, whose mesh object reads the quad from that same glTF file.
class GltfAndJson : public ::testing::Test {
 protected:
  void SetUp() override {
    test::GltfTestWriter w;
    const std::vector<float> positions{-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1};
    const std::vector<uint16_t> indices{0, 2, 1, 0, 3, 2};
    const int p = w.add_accessor(positions, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC3", 4);
    const int i = w.add_accessor(indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, "SCALAR", 6);
    Json& doc = w.doc();
    doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", p}}}, {"indices", i}, {"material", 0}}}}}};
    doc["materials"] = {{{"name", "Gold"}, {"extras", {{"facet", kGold}}}}};
    // yfov 0.6 rad; the camera 1 above the quad's centre and 3 back, pitched down by atan(1/3).
    doc["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.6}, {"znear", 0.1}}}}};
    const double pitch = -std::atan(1.0 / 3.0), tilt = -std::asin(0.6);
    doc["extensionsUsed"] = {"KHR_lights_punctual"};
    doc["extensions"]["KHR_lights_punctual"]["lights"] = {{{"type", "directional"}, {"intensity", 2.0}}};
    doc["nodes"] = {
        {{"mesh", 0}},
        {{"camera", 0}, {"translation", {0, 1, 3}}, {"rotation", {std::sin(pitch / 2), 0, 0, std::cos(pitch / 2)}}},
        {{"rotation", {std::sin(tilt / 2), 0, 0, std::cos(tilt / 2)}},
         {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}};
    doc["scenes"] = {{{"nodes", {0, 1, 2}}}};
    w.write_gltf(dir_ / "scene.gltf");
    // The same by hand: looking from (0, 1, 3) at the origin; light from +z tilted up to (0, 0.6, 0.8).
    std::ofstream(dir_ / "scene.json")
        << Json({{"camera", {{"position", {0, 1, 3}}, {"target", {0, 0, 0}}, {"fov_y", 0.6 * 180.0 / std::acos(-1.0)}}},
                 {"light", {{"direction", {0, 0.6, 0.8}}, {"irradiance", {2, 2, 2}}}},
                 {"materials", {{"Gold", kGold}}},
                 {"objects", {{{"type", "mesh"}, {"file", "scene.gltf"}, {"material", "Gold"}}}}})
               .dump();
  }
  Image render(const std::string& command, const std::string& scene) {
    const fs::path out = dir_ / (command + "_" + scene + ".exr");
    const auto r = run_command(kFacet + " " + command + " " + (dir_ / scene).string() +
                               " --width 24 --height 16 --no-preview --pixel-type float -o " + out.string() +
                               (command == "reference" ? " --grid 1" : ""));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return read_exr(out);
  }
  // Same size, every channel within `tolerance` (float noise of the two placements), and lit.
  static void expect_same(const Image& a, const Image& b, float tolerance) {
    ASSERT_EQ(a.rgb.size(), b.rgb.size());
    float worst = 0.0f, brightest = 0.0f;
    for (size_t k = 0; k < a.rgb.size(); ++k) {
      worst = std::max(worst, std::abs(a.rgb[k] - b.rgb[k]));
      brightest = std::max(brightest, a.rgb[k]);
    }
    EXPECT_GT(brightest, 0.05f);
    EXPECT_LE(worst, tolerance * brightest) << "worst difference " << worst << " of " << brightest;
  }
  const Json kGold = {{"type", "microflake"}, {"ndf", "ggx"}, {"param", 0.3}, {"albedo", {1.0, 0.77, 0.34}}};
  test::TempDir dir_;
};

TEST_F(GltfAndJson, RenderTheSameImageOnTheGpu) {
  expect_same(render("render", "scene.gltf"), render("render", "scene.json"), 1e-6f);
}

TEST_F(GltfAndJson, RenderTheSameImageOnTheCpu) {
  expect_same(render("reference", "scene.gltf"), render("reference", "scene.json"), 1e-6f);
}

TEST(GltfSceneCli, ARefusedFileIsOneLineAndWritesNothing) {
  test::TempDir dir;
  std::ofstream(dir / "nocamera.gltf")
      << R"({"asset": {"version": "2.0"}, "nodes": [{"name": "empty"}], "scenes": [{"nodes": [0]}]})";
  const auto r =
      run_command(kFacet + " render " + (dir / "nocamera.gltf").string() + " -o " + (dir / "x.exr").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err, "facet: error: " + (dir / "nocamera.gltf").string() +
                       ": has no camera in its scene; facet renders a scene through its perspective camera\n");
  EXPECT_FALSE(fs::exists(dir / "x.exr"));
}

}  // namespace gltf_scene_cli_test
}  // namespace facet
