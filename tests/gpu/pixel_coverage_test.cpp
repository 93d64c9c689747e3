// The direct pass dispatches, per tile, only the pixels whose rays may meet the scene (gpu/pixel_coverage.hpp)
// and writes the background elsewhere. The bound must hold every pixel the reference renderer sees an object
// in, must leave out what no ray reaches, and the frames must not depend on where tiles cut it.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cpu/reference_renderer.hpp"
#include "gpu/direct_pass.hpp"
#include "gpu/pixel_coverage.hpp"
#include "lambert_scenes.hpp"
#include "scene/scene_loader.hpp"
#include "support/facet_paths.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace pixel_coverage_test {

using gpu::PixelCoverage;
using gpu::PixelRect;
using gpu::SceneBounds;

// Every pixel the reference (5 x 5 sub-pixel centres) sees anything in lies in its tile's covered rectangle.
void expect_covers_what_the_reference_sees(const Scene& scene, int width, int height) {
  cpu::ReferenceOptions options;
  options.width = width;
  options.height = height;
  options.grid = 5;
  options.jitter = false;
  const Image reference = cpu::render_reference(scene, options);
  const PixelCoverage coverage(SceneBounds{scene}, scene.camera, width, height);
  int seen = 0;
  for (int tile : {4, 16, 64}) {
    for (int y0 = 0; y0 < height; y0 += tile)
      for (int x0 = 0; x0 < width; x0 += tile) {
        const PixelRect r = coverage.covered({x0, y0, std::min(x0 + tile, width), std::min(y0 + tile, height)});
        for (int y = y0; y < std::min(y0 + tile, height); ++y)
          for (int x = x0; x < std::min(x0 + tile, width); ++x) {
            if (!(reference.alpha[reference.index(x, y)] > 0.0f)) continue;
            ++seen;
            ASSERT_TRUE(x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1)
                << "tile " << tile << " pixel " << x << "," << y << " outside [" << r.x0 << "," << r.x1 << ")x[" << r.y0
                << "," << r.y1 << ")";
          }
      }
  }
  EXPECT_GT(seen, 0);  // the frame shows something
}

TEST(PixelCoverage, EveryPixelTheReferenceSeesAnObjectInIsCovered) {
  for (const char* name : {"default.json", "colormap_objects.json", "microsurface_terrain.json",
                           "microsurface_horizon.json", "diffraction_spheres.json", "snake_fingers.json",
                           "colormap_seams_cube.json", "showcase.json", "gltf_courtyard.gltf"}) {
    SCOPED_TRACE(name);
    expect_covers_what_the_reference_sees(load_scene(kScenes / name), 64, 36);
  }
  // Cameras inside a sphere, below the ground, rolled (up tilted), and with objects beside and behind them.
  Scene scene = test::lambert_spheres_scene();
  scene.camera.position = {-0.8, 0.7, 0.2};  // inside the first sphere
  expect_covers_what_the_reference_sees(scene, 48, 32);
  scene = test::lambert_spheres_scene();
  scene.camera.position = {0.5, -1.0, 4.0};  // below the ground, looking up through it
  scene.camera.target = {0.0, 1.0, 0.0};
  expect_covers_what_the_reference_sees(scene, 48, 32);
  scene = test::lambert_spheres_scene();
  scene.camera.up = glm::normalize(glm::dvec3(0.6, 1.0, 0.0));  // rolled: the horizon runs diagonally
  scene.camera.fov_y_deg = 100.0;
  scene.spheres.push_back({{3.0, 0.5, 5.5}, 0.6, 0});                 // beside the camera, partly behind its plane
  scene.meshes.push_back(test::pyramid({-2.0, 0.0, 6.5}, 0.8, 1.0));  // behind it
  expect_covers_what_the_reference_sees(scene, 48, 32);
}

// A tile no object reaches into is empty, and the rectangle hugs what an object covers.
TEST(PixelCoverage, LeavesOutWhatNoRayReaches) {
  Scene scene = test::lambert_spheres_scene();
  scene.planes.clear();
  scene.spheres = {{{0.0, 0.7, 0.0}, 0.5, 0}};  // seen straight on, in the middle of the frame
  scene.camera.target = {0.0, 0.7, 0.0};
  const PixelCoverage coverage(SceneBounds{scene}, scene.camera, 160, 90);
  EXPECT_TRUE(coverage.covered({0, 0, 16, 16}).empty());
  EXPECT_TRUE(coverage.covered({144, 74, 160, 90}).empty());
  const PixelRect whole = coverage.covered({0, 0, 160, 90});
  // The sphere spans 2 atan(0.5 / 6.04) of the 40° field of view: about 21 of 90 rows; its box a little more.
  EXPECT_GT(whole.height(), 20);
  EXPECT_LT(whole.height(), 32);
  EXPECT_EQ(whole.x0 + whole.x1, 160);  // centred
  // An infinite ground seen from above: the rows above its horizon are left out, those below kept.
  scene = test::lambert_spheres_scene();
  scene.spheres.clear();
  scene.camera.target = {0.0, 1.5, 0.0};  // level: the horizon is the middle row
  const PixelCoverage ground(SceneBounds{scene}, scene.camera, 160, 90);
  EXPECT_TRUE(ground.covered({0, 0, 160, 40}).empty());
  EXPECT_EQ(ground.covered({0, 50, 160, 90}), (PixelRect{0, 50, 160, 90}));
  const PixelRect across = ground.covered({0, 40, 160, 50});
  EXPECT_GE(across.y0, 43);
  EXPECT_LE(across.y0, 45);
  // So is a finite ground that reaches behind the camera (its box cannot be projected), and a height field's
  // slab seen from above it; from within the slab, the whole frame.
  Scene field = load_scene(kScenes / "microsurface_terrain.json");
  field.planes.front().size = glm::dvec2(40.0, 40.0);
  field.camera.target = field.camera.position + glm::dvec3(0.0, 0.0, -1.0);
  const PixelCoverage above(SceneBounds{field}, field.camera, 160, 90);
  EXPECT_TRUE(above.covered({0, 0, 160, 40}).empty());
  EXPECT_EQ(above.covered({0, 50, 160, 90}), (PixelRect{0, 50, 160, 90}));
  field.camera.position.y = 0.0;  // the terrain's heights span about +-3 sigma_h = +-36 mm around 0
  field.camera.target.y = 0.0;
  EXPECT_EQ(PixelCoverage(SceneBounds{field}, field.camera, 160, 90).covered({0, 0, 160, 40}),
            (PixelRect{0, 0, 160, 40}));
}

// Frames do not depend on where tiles cut the covered pixels: pixels written as background by the host in one
// tiling are rendered by the pass in another, through ss:3's nine strata, with every auxiliary output and
// filtered:adaptive's refinement, which the error estimate of the background's pixels steers too.
TEST(PixelCoverage, FramesAreTheSameWhereverTilesCutThem) {
  auto context = test::make_validated_context();
  Scene scene = test::lambert_spheres_scene();
  scene.planes.front().size = glm::dvec2(3.0, 2.0);  // a finite ground: background all round it
  for (const std::string name : {"ss:3", "filtered", "filtered:adaptive"}) {
    SCOPED_TRACE(name);
    gpu::RenderMethod method = gpu::RenderMethod::parse(name);
    method.aovs = {.depth = true, .normal = true, .uv = true, .error = name != "ss:3"};
    const Image whole = gpu::render_direct(*context, scene, 70, 45, method, nullptr, {}, 256);
    for (int tile : {8, 20}) {
      const Image tiled = gpu::render_direct(*context, scene, 70, 45, method, nullptr, {}, tile);
      ASSERT_EQ(tiled.channels.size(), whole.channels.size());
      for (size_t c = 0; c < whole.channels.size(); ++c)
        for (size_t i = 0; i < whole.pixel_count(); ++i)
          ASSERT_EQ(tiled.channels[c].values[i], whole.channels[c].values[i]) << tile << " " << c << " " << i;
      for (size_t i = 0; i < whole.pixel_count(); ++i) {
        ASSERT_EQ(tiled.at(i), whole.at(i)) << tile << " " << i;
        ASSERT_EQ(tiled.alpha[i], whole.alpha[i]) << tile << " " << i;
      }
    }
  }
  // At 8 x 8 tiles whole tiles are left out, so the comparison above met background written by the host.
  const PixelCoverage coverage(SceneBounds{scene}, scene.camera, 70, 45);
  EXPECT_TRUE(coverage.covered({0, 0, 8, 8}).empty());
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace pixel_coverage_test
}  // namespace facet
