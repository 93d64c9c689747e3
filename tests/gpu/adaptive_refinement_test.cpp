// filtered:adaptive (docs/error_estimate.md, "Adaptive refinement"): which pixels the budget picks, that a
// refined pixel is exactly filtered:ss:K's and every other pixel filtered's, and that refining lowers
// the error against the reference.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "common/error.hpp"
#include "cpu/reference_renderer.hpp"
#include "gpu/adaptive_refinement.hpp"
#include "gpu/direct_pass.hpp"
#include "image/metrics.hpp"
#include "scene/scene_loader.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace adaptive_refinement_test {

constexpr int kWidth = 64, kHeight = 36;

gpu::AdaptiveBudget error_budget(double error) {
  gpu::AdaptiveBudget budget;
  budget.error = error;
  return budget;
}

gpu::AdaptiveBudget time_budget(double ms) {
  gpu::AdaptiveBudget budget;
  budget.time_ms = ms;
  return budget;
}

Scene objects_scene() { return load_scene(std::string(FACET_SOURCE_DIR) + "/scenes/colormap_objects.json"); }

gpu::RenderMethod method(const std::string& name, gpu::AdaptiveBudget budget = {}, bool error_aov = false) {
  gpu::RenderMethod m = gpu::RenderMethod::parse(name);
  m.adaptive = budget;
  m.aovs.error = error_aov;
  return m;
}

Image render(vk::Context& context, const Scene& scene, const gpu::RenderMethod& m, gpu::RenderStats* stats = nullptr) {
  return gpu::render_direct(context, scene, kWidth, kHeight, m, stats);
}

std::vector<float> error_channel(const Image& image) {
  for (const NamedChannel& c : image.channels)
    if (c.name == "error") return c.values;
  ADD_FAILURE() << "no error channel";
  return {};
}

float max_abs_difference(const Image& a, const Image& b, std::size_t pixel) {
  const glm::vec3 d = glm::abs(a.at(pixel) - b.at(pixel));
  return std::max({d.x, d.y, d.z, std::abs(a.alpha[pixel] - b.alpha[pixel])});
}

// A sphere's shadow on a textured plane whose colour map is one colour, so that the texture term reads 0
// and the estimate is its edge term alone (eq. 3), seen from above: the plane, the sphere beside its shadow.
Scene shadow_scene() {
  const nlohmann::json document = nlohmann::json::parse(R"({
    "camera": {"position": [0, 6, 0.01], "target": [0, 0, 0], "up": [0, 0, -1], "fov_y": 60, "width": 64, "height": 36},
    "light": {"direction": [1, 1.5, 0.3], "irradiance": [3, 3, 3]},
    "ambient": [0.2, 0.2, 0.2],
    "materials": {
      "grey": {"type": "colormap_texture", "texture": {"noise": {"width": 32, "height": 32, "octaves": 3, "base_frequency": 4, "seed": 5}},
               "colormap": {"points": [[0, [0.6, 0.6, 0.6]], [1, [0.6, 0.6, 0.6]]]}},
      "clay": {"type": "lambert", "albedo": [0.8, 0.35, 0.25]}},
    "objects": [
      {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "grey"},
      {"type": "sphere", "center": [0.6, 1.0, 0], "radius": 0.5, "material": "clay"}]})");
  return parse_scene(document, std::string(FACET_SOURCE_DIR) + "/scenes/shadow.json");
}

// A shadow's edge on a textured surface is an edge of the estimate (eq. 3: the pass writes whether each
// hit's shadow ray reached the light): on the plane, away from the sphere's silhouette, exactly the pixels
// beside a shadow's edge (a 4-neighbour of another brightness: the plane is one colour) read an error.
TEST(AdaptiveRefinement, ShadowEdgesOfTexturedSurfacesAreEstimated) {
  auto context = test::make_validated_context();
  const Scene scene = shadow_scene();
  const Image image = render(*context, scene, method("filtered", {}, true));
  const std::vector<float> error = error_channel(image);
  const auto plane = [&](int x, int y) {  // the plane's pixels are a little above 0.2 in brightness, the sphere's red
    const glm::vec3 c = image.at(image.index(x, y));
    return std::abs(c.r - c.b) < 1e-3f;
  };
  int edges = 0;
  for (int y = 1; y + 1 < kHeight; ++y)
    for (int x = 1; x + 1 < kWidth; ++x) {
      const int neighbours[4][2] = {{x - 1, y}, {x + 1, y}, {x, y - 1}, {x, y + 1}};
      bool inside = plane(x, y), shadow_edge = false;
      for (const auto& [nx, ny] : neighbours) {
        inside = inside && plane(nx, ny);
        shadow_edge = shadow_edge || std::abs(image.at(image.index(nx, ny)).r - image.at(image.index(x, y)).r) > 0.1f;
      }
      if (!inside) continue;
      const float e = error[image.index(x, y)];
      EXPECT_EQ(e > 0.0f, shadow_edge) << "(" << x << ", " << y << ") error " << e;
      edges += shadow_edge ? 1 : 0;
    }
  EXPECT_GT(edges, 10);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// filtered:adaptive[:K]: K = 8 unless given, in [2, 16]; the name survives a round trip.
TEST(AdaptiveRefinement, MethodNamesItsStrata) {
  EXPECT_EQ(gpu::RenderMethod::parse("filtered:adaptive").adaptive_samples_per_axis, 8);
  EXPECT_EQ(gpu::RenderMethod::parse("filtered:adaptive").texture, gpu::RenderMethod::Texture::Filtered);
  EXPECT_EQ(gpu::RenderMethod::parse("filtered:adaptive:4").adaptive_samples_per_axis, 4);
  for (const char* text : {"filtered:adaptive", "filtered:adaptive:2", "filtered:adaptive:4", "filtered:adaptive:16"})
    EXPECT_EQ(gpu::RenderMethod::parse(text).name(), text);
  EXPECT_EQ(gpu::RenderMethod::parse("filtered:adaptive:8").name(), "filtered:adaptive");
  for (const char* text : {"filtered:adaptive:1", "filtered:adaptive:17", "filtered:adaptive:", "filtered:adaptive4",
                           "filtered:adaptive:ss:2"})
    EXPECT_THROW(gpu::RenderMethod::parse(text), Error) << text;
}

// The levels, the work and eq. 7 of docs/error_estimate.md, by hand: on a textured pixel a stratum of K >= 4
// lays one row of taps (s = 1), of K = 2 and K = 3 a 2 x 2 split (s = ceil(4 / K) = 2), the first pass 2 x 2
// (K = 1); an untextured pixel costs its rays.
TEST(AdaptiveRefinement, LevelsWorkAndPredictedError) {
  EXPECT_EQ(gpu::refinement_levels(2), (std::vector<int>{2}));
  EXPECT_EQ(gpu::refinement_levels(3), (std::vector<int>{2, 3}));
  EXPECT_EQ(gpu::refinement_levels(8), (std::vector<int>{2, 4, 8}));
  EXPECT_EQ(gpu::refinement_levels(12), (std::vector<int>{2, 4, 8, 12}));
  EXPECT_EQ(gpu::refinement_cost(1, true), 5.0);    // 1 (1 + 2^2)
  EXPECT_EQ(gpu::refinement_cost(2, true), 20.0);   // 4 (1 + 2^2)
  EXPECT_EQ(gpu::refinement_cost(3, true), 45.0);   // 9 (1 + 2^2)
  EXPECT_EQ(gpu::refinement_cost(4, true), 32.0);   // 16 (1 + 1)
  EXPECT_EQ(gpu::refinement_cost(8, true), 128.0);  // 64 (1 + 1)
  EXPECT_EQ(gpu::refinement_cost(1, false), 1.0);
  EXPECT_EQ(gpu::refinement_cost(8, false), 64.0);
  // A textured pixel's texture error falls with the taps per axis (2 in the first pass, 4 at K = 2 and 4, 8
  // at K = 8); edge error over K; an untextured pixel's whole estimate over K.
  const gpu::PixelEstimate texture{0.4f, 0.0f, true}, edge{0.4f, 0.4f, true}, both{0.7f, 0.4f, true},
      contrast{0.5f, 0.4f, false};
  EXPECT_NEAR(gpu::predicted_squared_error(texture, 1), 0.16, 1e-7);
  EXPECT_NEAR(gpu::predicted_squared_error(texture, 2), 0.04, 1e-7);
  EXPECT_NEAR(gpu::predicted_squared_error(texture, 4), 0.04, 1e-7);
  EXPECT_NEAR(gpu::predicted_squared_error(texture, 8), 0.01, 1e-7);
  EXPECT_NEAR(gpu::predicted_squared_error(edge, 4), 0.01, 1e-7);
  EXPECT_NEAR(gpu::predicted_squared_error(both, 2), 0.0225 + 0.04, 1e-7);
  EXPECT_NEAR(gpu::predicted_squared_error(contrast, 2), (0.01 + 0.16) / 4, 1e-7);
}

TEST(AdaptiveRefinement, PlansByEstimateWithinTheBudget) {
  using gpu::PixelEstimate;
  using gpu::RefinedPixel;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<PixelEstimate> pixels = {{0.1f, 0.0f, true}, {0.5f, 0.5f, true}, {0.0f, 0.0f, true},
                                             {nan, nan, true},   {0.5f, 0.0f, true}, {0.2f, 0.0f, true},
                                             {0.0f, 0.0f, true}, {0.05f, 0.0f, true}};
  // Error budget E = 0.15: every estimate above it (NaN and zero never), largest first, ties by index, each
  // at the fewest strata eq. 7 puts at or below E: the edge 0.5 needs 0.25 / K^2 <= 0.0225, K = 4; the
  // texture 0.5 gets 0.0625 at K = 2 and 4, 0.0156 at 8; the texture 0.2 gets 0.01 at K = 2. With K at most
  // 4, the texture 0.5 stops there.
  EXPECT_EQ(gpu::plan_refinement(pixels, error_budget(0.15), 8, 0.0),
            (std::vector<RefinedPixel>{{1, 4, true}, {4, 8, true}, {5, 2, true}}));
  EXPECT_EQ(gpu::plan_refinement(pixels, error_budget(0.15), 4, 0.0),
            (std::vector<RefinedPixel>{{1, 4, true}, {4, 4, true}, {5, 2, true}}));
  // Work: the largest predicted squared error removed per unit first. Edge pixels of 0.4 and 0.2:
  // 0.4 from 1 to 2 removes 0.12 for 20 (0.006 a unit), then from 2 to 4 0.03 for 12 (0.0025), more than 0.2
  // from 1 to 2 (0.03 for 20: 0.0015); 0.4 from 4 to 8 (0.0075 for 96) comes last.
  const std::vector<PixelEstimate> edges = {{0.4f, 0.4f, true}, {0.2f, 0.2f, true}};
  EXPECT_EQ(gpu::plan_refinement(edges, {}, 8, 19.0), (std::vector<RefinedPixel>{}));
  EXPECT_EQ(gpu::plan_refinement(edges, {}, 8, 20.0), (std::vector<RefinedPixel>{{0, 2, true}}));
  EXPECT_EQ(gpu::plan_refinement(edges, {}, 8, 51.0), (std::vector<RefinedPixel>{{0, 4, true}}));
  EXPECT_EQ(gpu::plan_refinement(edges, {}, 8, 52.0), (std::vector<RefinedPixel>{{0, 4, true}, {1, 2, true}}));
  EXPECT_EQ(gpu::plan_refinement(edges, {}, 8, 1e9), (std::vector<RefinedPixel>{{0, 8, true}, {1, 8, true}}));
  EXPECT_EQ(gpu::plan_refinement(edges, {}, 2, 1e9), (std::vector<RefinedPixel>{{0, 2, true}, {1, 2, true}}));
  // A textured pixel takes K = 2 (the taps of K = 4 for less work). An untextured one of the same estimate
  // pays rays only: 1 to 2 removes 0.12 for 4, to 4 0.15 for 16, to 8 0.1575 for 64; then 2 to 4 removes
  // 0.03 for 12 (0.0025 a unit), more than 4 to 8's 0.0075 for 48: 4 + 12 + 48 = 64 units reach K = 8.
  const std::vector<PixelEstimate> texture = {{0.4f, 0.0f, true}}, contrast = {{0.4f, 0.0f, false}};
  EXPECT_EQ(gpu::plan_refinement(texture, {}, 8, 100.0), (std::vector<RefinedPixel>{{0, 2, true}}));
  EXPECT_EQ(gpu::plan_refinement(texture, {}, 8, 1e9), (std::vector<RefinedPixel>{{0, 8, true}}));
  EXPECT_EQ(gpu::plan_refinement(contrast, {}, 8, 15.0), (std::vector<RefinedPixel>{{0, 2, false}}));
  EXPECT_EQ(gpu::plan_refinement(contrast, {}, 8, 63.0), (std::vector<RefinedPixel>{{0, 4, false}}));
  EXPECT_EQ(gpu::plan_refinement(contrast, {}, 8, 64.0), (std::vector<RefinedPixel>{{0, 8, false}}));
  EXPECT_EQ(gpu::default_refinement_work(8), 32.0);

  const std::vector<RefinedPixel> plan = {{3, 2, true}, {1, 4, true}, {0, 8, false}};  // 20, 32, 64 units
  EXPECT_EQ(gpu::pixels_within_work(plan, 19.0), 0u);
  EXPECT_EQ(gpu::pixels_within_work(plan, 51.0), 1u);
  EXPECT_EQ(gpu::pixels_within_work(plan, 52.0), 2u);
  EXPECT_EQ(gpu::pixels_within_work(plan, 116.0), 3u);
  EXPECT_EQ(gpu::pixels_within_work(plan, -1.0), 0u);
}

// With an error budget E the pixels whose first-pass estimate exceeds E are filtered:ss:2's pixels and all
// others filtered's: the first pass is `filtered` with the estimate the plan ranks by (eq. 1, no tiling term:
// filtered:adaptive with a budget no pixel exceeds writes it), the second renders the
// listed pixels' strata as filtered:ss:2 renders them (from K = 4 on a refined stratum lays one row of
// taps where filtered:ss:K splits it: docs/error_estimate.md, "Refined strata"). A time budget cuts the
// same ranking.
TEST(AdaptiveRefinement, RefinedPixelsAreFilteredPerStratumAndTheRestFiltered) {
  auto context = test::make_validated_context();
  const Scene scene = objects_scene();
  const Image first = render(*context, scene, method("filtered:adaptive:2", error_budget(1e9), true));
  const Image strata = render(*context, scene, method("filtered:ss:2"));
  const std::vector<float> estimate = error_channel(first);
  std::vector<float> sorted = estimate;
  std::ranges::sort(sorted);
  const double budget = sorted[sorted.size() * 3 / 4];  // about a quarter of the pixels above it
  gpu::RenderStats stats;
  const Image adaptive = render(*context, scene, method("filtered:adaptive:2", error_budget(budget)), &stats);
  std::size_t refined = 0, differing_strata = 0;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const bool refine = estimate[i] > budget;
    refined += refine;
    EXPECT_LE(max_abs_difference(adaptive, refine ? strata : first, i), 1e-6f) << "pixel " << i;
    differing_strata += max_abs_difference(strata, first, i) > 1e-3f;
  }
  EXPECT_EQ(stats.refined_pixels, refined);
  EXPECT_GT(refined, estimate.size() / 8);
  EXPECT_GT(differing_strata, estimate.size() / 8);  // the comparison above tells the two apart

  // A time budget: none left after the first pass refines nothing; an ample one every estimated pixel.
  gpu::RenderStats none, all;
  const Image unrefined = render(*context, scene, method("filtered:adaptive", time_budget(1e-9)), &none);
  EXPECT_EQ(none.refined_pixels, 0u);
  for (std::size_t i = 0; i < first.pixel_count(); ++i) ASSERT_EQ(max_abs_difference(unrefined, first, i), 0.0f);
  render(*context, scene, method("filtered:adaptive", time_budget(1e9)), &all);
  EXPECT_EQ(all.refined_pixels,
            static_cast<std::size_t>(std::ranges::count_if(estimate, [](float e) { return e > 0; })));
}

// The refinement renders each level's pixels as one list of strata, as many pixels a dispatch as the list
// holds, at least one pixel's K^2 strata: with 8 x 8 tiles (64 entries) K = 16 takes a dispatch per pixel,
// with the default tiles one for all. The pixels do not depend on it (each is its strata's sum in one order),
// and the error budget refines at every level up to 16.
TEST(AdaptiveRefinement, PixelsDoNotDependOnHowManyStrataADispatchHolds) {
  auto context = test::make_validated_context();
  const Scene scene = objects_scene();
  const gpu::RenderMethod m = method("filtered:adaptive:16", error_budget(0.004), true);
  gpu::RenderStats small_stats, large_stats;
  const Image small = gpu::render_direct(*context, scene, kWidth, kHeight, m, &small_stats, {}, 8);
  const Image large = gpu::render_direct(*context, scene, kWidth, kHeight, m, &large_stats, {}, 64);
  EXPECT_GT(small_stats.refined_pixels, 0u);
  EXPECT_EQ(small_stats.refined_pixels, large_stats.refined_pixels);
  for (std::size_t i = 0; i < small.pixel_count(); ++i) ASSERT_EQ(max_abs_difference(small, large, i), 0.0f) << i;
  EXPECT_EQ(error_channel(small), error_channel(large));
}

// Against a 16x16 reference: the default budget (2 more rays per pixel on average) and an error budget
// that refines every pixel with a non-zero estimate each lower filtered's error, the larger budget more.
// Measured (64x36, 2026-11-27): filtered 0.0381, default 0.0142, every estimated pixel 0.0096 (filtered:ss:4
// 0.0094: the pixels estimated exact are those the strata leave unchanged; the refined strata lay one row of
// taps where filtered:ss:4 splits them).
TEST(AdaptiveRefinement, ConvergesTowardTheReferenceAsTheBudgetGrows) {
  auto context = test::make_validated_context();
  const Scene scene = objects_scene();
  cpu::ReferenceOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.grid = 16;
  options.seed = 5;
  const Image reference = cpu::render_reference(scene, options);
  const double filtered = rmse(render(*context, scene, method("filtered")), reference);
  const double by_default = rmse(render(*context, scene, method("filtered:adaptive")), reference);
  const double everywhere = rmse(render(*context, scene, method("filtered:adaptive", error_budget(1e-9))), reference);
  const double strata = rmse(render(*context, scene, method("filtered:ss:4")), reference);
  EXPECT_LT(by_default, 0.8 * filtered);
  EXPECT_LT(everywhere, 0.8 * by_default);
  EXPECT_LE(everywhere, 1.1 * strata);
}

}  // namespace adaptive_refinement_test
}  // namespace facet
