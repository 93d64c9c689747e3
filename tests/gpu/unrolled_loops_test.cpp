// The direct pass unrolls its short loops to trip counts taken from the scene (specialization constants,
// docs/render_speed.md, "Loops on lavapipe"): colour-map walks and searches to the scene's longest map, the
// plane and sphere loops to the scene's counts. A trip past a shorter map's last point, or a search trip
// after the segment is found, must add nothing; so a frame must not change when an unused material or
// object raises the trip counts, or pushes them past the unrolled limit into a loop.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gpu/direct_pass.hpp"
#include "lambert_scenes.hpp"
#include "scene/scene_loader.hpp"
#include "support/facet_paths.hpp"
#include "support/frame_difference.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace unrolled_loops_test {

using gpu::RenderMethod;

// The scene's first colour-mapped texture again, with an `n`-point map of `interpolation` (linear ramp of
// grey levels), as a material no object uses: it only raises the scene's longest map.
Scene with_unused_map(Scene scene, int n, Colormap::Interpolation interpolation) {
  std::vector<double> positions;
  std::vector<glm::dvec3> colours;
  for (int i = 0; i < n; ++i) {
    positions.push_back(static_cast<double>(i) / (n - 1));
    colours.push_back(glm::dvec3(static_cast<double>(i % 3) / 2.0, 0.5, static_cast<double>(i) / (n - 1)));
  }
  for (const Material& m : scene.materials)
    if (const auto* t = std::get_if<ColormapTextureMaterial>(&m)) {
      ColormapTextureMaterial unused = *t;
      unused.colormap = Colormap(positions, colours, interpolation);
      scene.materials.push_back(unused);
      return scene;
    }
  ADD_FAILURE() << "the scene has no colour-mapped texture";
  return scene;
}

// Scenes a and b rendered by each of `methods` at 48x27: the same bits.
void expect_same_frames(vk::Context& context, const Scene& a, const Scene& b,
                        std::initializer_list<const char*> methods) {
  for (const char* name : methods) {
    const RenderMethod method = RenderMethod::parse(name);
    EXPECT_EQ(test::differing_samples(gpu::render_direct(context, a, 48, 27, method),
                                      gpu::render_direct(context, b, 48, 27, method)),
              0)
        << name;
  }
}

RenderMethod filtered_with_error() {
  RenderMethod method = RenderMethod::parse("filtered");
  method.aovs.error = true;  // the spread walks the maps' points too (texture_sampling.glsl)
  return method;
}

// The noise plane's 3-point step map walked in 2, 6 and 16 trips (an unused 7- and 17-point step map; the
// latter is past the unrolled limit, a loop), the mean and the error estimate's spread: the same bits.
TEST(UnrolledLoops, StepMapWalksDoNotDependOnTheScenesLongestMap) {
  auto context = test::make_validated_context();
  const Scene plain = load_scene(kScenes / "colormap_noise_plane.json");
  const RenderMethod method = filtered_with_error();
  const Image reference = gpu::render_direct(*context, plain, 48, 27, method);
  for (int n : {7, 17}) {
    const Image longer = gpu::render_direct(
        *context, with_unused_map(plain, n, Colormap::Interpolation::Steps), 48, 27, method);
    EXPECT_EQ(test::differing_samples(reference, longer), 0) << n << "-point map beside it";
  }
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// The anisotropic plane's 5-point linear map walked in 5 and 12 trips, and in a loop (an unused 12- and
// 17-point linear map). The unrolled walks add exact zeros; the loop is compiled apart, so its float
// contractions may differ from the unrolled code's by rounding (1e-6 relative at most).
TEST(UnrolledLoops, LinearMapWalksDoNotDependOnTheScenesLongestMap) {
  auto context = test::make_validated_context();
  const Scene plain = load_scene(kScenes / "colormap_anisotropic.json");
  const RenderMethod method = filtered_with_error();
  const Image reference = gpu::render_direct(*context, plain, 48, 27, method);
  const Image unrolled_longer =
      gpu::render_direct(*context, with_unused_map(plain, 12, Colormap::Interpolation::Linear), 48, 27, method);
  EXPECT_EQ(test::differing_samples(reference, unrolled_longer), 0);
  const Image looped =
      gpu::render_direct(*context, with_unused_map(plain, 17, Colormap::Interpolation::Linear), 48, 27, method);
  ASSERT_EQ(looped.rgb.size(), reference.rgb.size());
  for (size_t i = 0; i < looped.rgb.size(); ++i)
    ASSERT_NEAR(looped.rgb[i], reference.rgb[i], 1e-6f * (1.0f + std::abs(reference.rgb[i]))) << "sample " << i;
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// colormap_at's bisection over the noise plane's 3-point map in 1 trip, and in 9 (an unused 300-point map):
// `naive` looks every pixel up there.
TEST(UnrolledLoops, ColourMapSearchesDoNotDependOnTheScenesLongestMap) {
  auto context = test::make_validated_context();
  const Scene plain = load_scene(kScenes / "colormap_noise_plane.json");
  const RenderMethod naive = RenderMethod::parse("naive");
  const Image reference = gpu::render_direct(*context, plain, 48, 27, naive);
  const Image longer =
      gpu::render_direct(*context, with_unused_map(plain, 300, Colormap::Interpolation::Linear), 48, 27, naive);
  EXPECT_EQ(test::differing_samples(reference, longer), 0);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// The noise plane under a built-in 256-point map (evenly spaced: colormap_at's search starts from the division's
// three segments, in 2 trips) and under the same map with one position moved by 1e-8 of a step (no longer evenly
// spaced in double, the same positions in float: the whole map's bisection, 8 trips): `naive` (every pixel looked
// up) and `mip` (every tap) find the same segments, linear and in steps.
TEST(UnrolledLoops, EvenlySpacedMapsAreSearchedFromTheDivisionsSegment) {
  auto context = test::make_validated_context();
  const Scene plain = load_scene(kScenes / "colormap_noise_plane.json");
  for (const auto interpolation : {Colormap::Interpolation::Linear, Colormap::Interpolation::Steps}) {
    const Colormap viridis = builtin_colormap("viridis", interpolation, {0.1, 0.9});
    std::vector<double> moved = viridis.positions();
    moved[100] += 1e-8 / 255.0;
    const Colormap uneven(moved, viridis.colours(), interpolation, viridis.domain());
    ASSERT_TRUE(viridis.evenly_spaced());
    ASSERT_FALSE(uneven.evenly_spaced());
    ASSERT_EQ(static_cast<float>(moved[100]), static_cast<float>(viridis.positions()[100]));
    Scene even_scene = plain, uneven_scene = plain;
    for (Scene* scene : {&even_scene, &uneven_scene})
      for (Material& m : scene->materials)
        if (auto* t = std::get_if<ColormapTextureMaterial>(&m)) t->colormap = scene == &even_scene ? viridis : uneven;
    expect_same_frames(*context, uneven_scene, even_scene, {"naive", "mip"});
  }
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Two spheres on a plane (unrolled loops of 1 and 2 trips) against the same scene with far objects
// that neither show nor shadow anything (planes and spheres past four: loops over the scene's counts).
TEST(UnrolledLoops, PlaneAndSphereLoopsUnrolledOrNotHitTheSame) {
  auto context = test::make_validated_context();
  const Scene plain = test::lambert_spheres_scene();
  Scene crowded = plain;
  for (int i = 0; i < 4; ++i) {
    // Below the ground plane, which hides them, and below every lit point: never hit, never in a shadow ray.
    crowded.planes.push_back(
        {{0.0, -50.0 - i, 0.0}, {0.0, -1.0, 0.0}, 0, glm::dvec3(1.0, 0.0, 0.0), glm::dvec2(1.0), glm::dvec2(1.0)});
    crowded.spheres.push_back({{0.0, -60.0 - 3.0 * i, 40.0}, 0.5, 1});
  }
  expect_same_frames(*context, plain, crowded, {"naive", "ss:2"});
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace unrolled_loops_test
}  // namespace facet
