// The work counter (gpu/work_counter.hpp, gpu/work_per_pixel.hpp) against a count by hand: one
// infinite Lambert plane under a light from above, `naive`. Counted from the GLSL as glslang
// translates it (FMA-equivalents: add, multiply, fma = 1 per lane; division and sqrt 3; dot of n = n;
// length n + 3; normalize 2n + 3; max 1):
//   main       step = 1 / k: 3; film = pixel + (stratum + 0.5) step: 2 + 2 + 2             =   9
//   radiance   camera_ray(film): 2 film / resolution - 1: 2 + 6 + 2; forward + x right - y up:
//              3 + 3 + 3 + 3; normalize: 9                                                      =  31
//   trace      intersect_plane: dot, abs (4), (point - o) . n / denom (9); on a hit o + t d (6)    13 / 19
//   shade      (hits only) p = o + t d: 6; normalize(n): 9; dot(n, d): 3; dot(n, l): 3; the shadow
//              ray's origin p + n (offset max(1, length p)): 6 + 1 + 1 + 3 + 3; occluded skips
//              the plane it leaves: 0; lambert_radiance: dot 3, max 1, albedo / pi 3, cos v 1,
//              E (cos v) 3, + ambient 3, product 3; + diffracted 3                                 =  55
// so a hit costs 9 + 31 + 19 + 55 = 114 and a miss 9 + 31 + 13 = 53. Texel fetches: plane_at is 5
// texels, material_at 4: a hit reads the plane (trace), its material (shade) and the plane again
// (occluded): 14; a miss 5.
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "gpu/direct_pass.hpp"
#include "gpu/work_counter.hpp"
#include "gpu/work_per_pixel.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace work_count_test {

constexpr int kWidth = 24, kHeight = 16;

// The camera looks just below the horizon: the upper rows miss, the lower ones hit the plane.
Scene plane_scene() {
  Scene scene;
  scene.camera.position = {0.0, 1.0, 4.0};
  scene.camera.target = {0.0, 0.8, 0.0};
  scene.camera.fov_y_deg = 60.0;
  scene.light.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  scene.light.irradiance = {3.0, 3.0, 3.0};
  scene.ambient = {0.1, 0.1, 0.1};
  scene.materials = {LambertMaterial{{0.7, 0.6, 0.5}}};
  scene.planes.push_back({{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0});
  return scene;
}

TEST(WorkCount, PlaneSceneNaiveMatchesTheCountByHand) {
  auto context = test::make_validated_context();
  const Scene scene = plane_scene();
  const gpu::WorkCount work = gpu::count_work(*context, scene, {}, kWidth, kHeight);
  // Which pixels hit: the coverage of the ordinary frame.
  const Image frame = gpu::render_direct(*context, scene, kWidth, kHeight);
  int hits = 0;
  for (std::size_t i = 0; i < frame.pixel_count(); ++i) {
    const bool hit = frame.alpha[i] > 0.5f;
    hits += hit ? 1 : 0;
    EXPECT_EQ(work.per_pixel.at(i).r, hit ? 114.0f : 53.0f) << "pixel " << i;
    EXPECT_EQ(work.per_pixel.at(i).g, hit ? 14.0f : 5.0f) << "pixel " << i;
  }
  ASSERT_GT(hits, 0);
  ASSERT_LT(hits, kWidth * kHeight);
  const double n = kWidth * kHeight;
  EXPECT_DOUBLE_EQ(work.fma_per_pixel, (114.0 * hits + 53.0 * (n - hits)) / n);
  EXPECT_DOUBLE_EQ(work.reads_per_pixel, (14.0 * hits + 5.0 * (n - hits)) / n);
}

// ss:K counts each of its K^2 samples: every pixel's work is K^2 times a sample's.
TEST(WorkCount, SupersamplingCountsEverySample) {
  auto context = test::make_validated_context();
  Scene scene = plane_scene();
  scene.camera.target = {0.0, -3.0, 0.0};  // 45° down, 30° half field of view: every ray hits the plane
  const gpu::WorkCount work = gpu::count_work(*context, scene, gpu::RenderMethod::parse("ss:2"), kWidth, kHeight);
  for (std::size_t i = 0; i < work.per_pixel.pixel_count(); ++i) {
    EXPECT_EQ(work.per_pixel.at(i).r, 4.0f * 114.0f) << "pixel " << i;
    EXPECT_EQ(work.per_pixel.at(i).g, 4.0f * 14.0f) << "pixel " << i;
  }
}

TEST(WorkCount, RefusesModulesWithoutCounters) {
  const std::vector<uint32_t> not_spirv = {1, 2, 3, 4, 5, 6};
  EXPECT_THROW(gpu::instrument_work_counts(not_spirv), Error);
  // A valid header and nothing else: no counters declared.
  const std::vector<uint32_t> empty = {0x07230203u, 0x00010500u, 0u, 1u, 0u};
  EXPECT_THROW(gpu::instrument_work_counts(empty), Error);
}

}  // namespace work_count_test
}  // namespace facet
