// ss:K as K^2 dispatches, one stratum each, accumulated in the tile's pixels (gpu/direct_pass.cpp).
// Stratum (sx, sy) of pixel (x, y) traces the ray through film point (x + (sx + 1/2)/K, y + (sy + 1/2)/K),
// which is the centre of pixel (K x + sx, K y + sy) of a frame K times larger: ss:K at W x H must equal
// `naive` at K W x K H averaged over K x K blocks, a render that never accumulates across dispatches.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <variant>

#include <gtest/gtest.h>

#include "diffraction/plate_scene.hpp"
#include "gpu/direct_pass.hpp"
#include "lambert_scenes.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

Image block_mean(const Image& fine, int k) {
  Image coarse(fine.width / k, fine.height / k);
  for (int y = 0; y < coarse.height; ++y)
    for (int x = 0; x < coarse.width; ++x) {
      glm::dvec3 sum(0.0);
      for (int sy = 0; sy < k; ++sy)
        for (int sx = 0; sx < k; ++sx) sum += glm::dvec3(fine.at(k * x + sx, k * y + sy));
      coarse.set(x, y, glm::vec3(sum / double(k * k)));
    }
  return coarse;
}

double largest(glm::dvec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

TEST(Supersampling, StrataEqualTheNaiveFrameAtKTimesTheResolution) {
  auto context = test::make_validated_context();
  const Scene scene = test::lambert_spheres_scene();
  constexpr int kWidth = 40, kHeight = 24, kK = 3;  // K not a power of 2: the final 1/K^2 is inexact
  const Image strata = gpu::render_direct(*context, scene, kWidth, kHeight, gpu::RenderMethod::parse("ss:3"), nullptr,
                                          {}, 16);  // several tiles, some partial
  const Image reference = block_mean(gpu::render_direct(*context, scene, kK * kWidth, kK * kHeight), kK);
  // The two film points differ by float rounding of (x + (s + 1/2)/K)/W against (K x + s + 1/2)/(K W),
  // ~1e-7 of the ray direction, which moves a smooth shaded value (<= ~3.5 here) by ~1e-6; the sums
  // differ in order and precision (float strata vs a double block mean) by ~K^2 ulp ~ 1e-6. Tolerance
  // 1e-4 (x30). A stratum whose ray grazes a silhouette or shadow edge may flip; <= 1% of pixels.
  size_t within = 0;
  double worst = 0.0;
  for (size_t i = 0; i < strata.pixel_count(); ++i) {
    const double e = largest(glm::dvec3(strata.at(i)) - glm::dvec3(reference.at(i)));
    if (e <= 1e-4) ++within, worst = std::max(worst, e);
  }
  std::cout << "[ measured ] " << within << " of " << strata.pixel_count() << " pixels within 1e-4, worst " << worst
            << "\n";
  EXPECT_GE(static_cast<double>(within), 0.99 * static_cast<double>(strata.pixel_count()));
  // Supersampling did something: edges are smoother than the 1-ray frame's.
  const Image one_ray = gpu::render_direct(*context, scene, kWidth, kHeight);
  size_t differing = 0;
  for (size_t i = 0; i < strata.pixel_count(); ++i)
    differing += largest(glm::dvec3(strata.at(i)) - glm::dvec3(one_ray.at(i))) > 1e-3;
  EXPECT_GT(differing, strata.pixel_count() / 50);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

TEST(Supersampling, DiffractionRaysNearTheLoopLimitAreNotCutShort) {
  // 800 wavelengths x 25 bins x 10 Taylor terms: 60 801 loop iterations per ray, just under lavapipe's
  // 65 535 per invocation (docs/diffraction.md). Looping over 9 strata in one invocation would end the
  // spectral loops early and silently; one stratum per dispatch must give the 3x frame's block means.
  Scene scene = test::plate_scene(8.0);
  scene.ambient = {0.1, 0.1, 0.1};
  auto& m = std::get<DiffractionMaterial>(scene.materials[0]);
  m.wavelengths = 800;
  m.base_albedo = {0.2, 0.1, 0.05};
  scene.camera.position = {0.0, 0.0, 1.0};
  scene.camera.target = {0.0, 0.0, 0.0};
  scene.camera.fov_y_deg = 90.0;
  auto context = test::make_validated_context();
  // Orders -2..2 across the frame; the middle stratum row looks along v = 0, where they peak.
  constexpr int kWidth = 16, kHeight = 1;
  const Image strata = gpu::render_direct(*context, scene, kWidth, kHeight, gpu::RenderMethod::parse("ss:3"));
  const Image reference = block_mean(gpu::render_direct(*context, scene, 3 * kWidth, 3 * kHeight), 3);
  double peak = 0.0, worst = 0.0;
  for (size_t i = 0; i < strata.pixel_count(); ++i) {
    peak = std::max(peak, largest(glm::dvec3(reference.at(i))));
    worst = std::max(worst, largest(glm::dvec3(strata.at(i)) - glm::dvec3(reference.at(i))));
  }
  // Same rays up to the film rounding above; on a peak's flank the BRDF changes by ~140 relative per
  // radian (DiffractionRender.GpuMatchesTheDoubleTwin), so ~2e-5 of the peak; 1e-4 of it allowed.
  // A cut-short spectral loop would lose whole wavelength bands: errors of order the peak.
  std::cout << "[ measured ] max |ss:3 - 3x block mean| = " << worst << " of peak " << peak << "\n";
  ASSERT_GT(peak, 1.0);
  EXPECT_LE(worst, 1e-4 * peak);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace
}  // namespace facet
