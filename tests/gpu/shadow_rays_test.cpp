// Shadow rays of the GPU pass (any-hit traversal that skips the plane a point lies on, and its sphere
// seen from outside; shaders/render/trace.glsl `occluded`) against the CPU twin's Embree occlusion
// queries, on the cases direct_pass_test does not cover: a plane alone, finite planes and a mesh as
// occluders of spheres and planes, and a camera inside a sphere, where the sphere must not be skipped.
#include <algorithm>
#include <cmath>
#include <iostream>

#include <gtest/gtest.h>

#include "cpu/direct_cpu.hpp"
#include "gpu/direct_pass.hpp"
#include "lambert_scenes.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace shadow_rays_test {

constexpr int kWidth = 96, kHeight = 64;

double largest(glm::dvec3 v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Float rays against double ones move smooth shaded values (<= ~4 here) by ~1e-6: 1e-4 is a 30x
// margin (as direct_pass_test). A pixel whose shadow ray grazes an occluder's edge may flip
// visibility between float and double: at most 1% of the pixels.
void expect_gpu_matches_cpu(const Scene& scene) {
  auto context = test::make_validated_context();
  const Image gpu = gpu::render_direct(*context, scene, kWidth, kHeight, {}, nullptr, {}, 40);  // partial tiles
  const Image cpu = cpu::render_direct_cpu(scene, kWidth, kHeight);
  size_t within = 0;
  double worst = 0.0;
  for (size_t i = 0; i < gpu.pixel_count(); ++i) {
    const double e = largest(glm::dvec3(gpu.at(i)) - glm::dvec3(cpu.at(i)));
    if (e <= 1e-4) ++within, worst = std::max(worst, e);
  }
  std::cout << "[ measured ] " << within << " of " << gpu.pixel_count() << " pixels within 1e-4, worst " << worst
            << "\n";
  EXPECT_GE(static_cast<double>(within), 0.99 * static_cast<double>(gpu.pixel_count()));
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// The fraction of pixels whose CPU render changes when `without` replaces `scene`: the occluders
// under test must cast visible shadows.
double changed_fraction(const Scene& scene, const Scene& without) {
  const Image a = cpu::render_direct_cpu(scene, kWidth, kHeight), b = cpu::render_direct_cpu(without, kWidth, kHeight);
  size_t changed = 0;
  for (size_t i = 0; i < a.pixel_count(); ++i) changed += largest(glm::dvec3(a.at(i)) - glm::dvec3(b.at(i))) > 1e-3;
  return static_cast<double>(changed) / static_cast<double>(a.pixel_count());
}

Scene lit_scene() {
  Scene scene;
  scene.camera.position = {0.0, 2.0, 6.0};
  scene.camera.target = {0.0, 0.5, 0.0};
  scene.camera.fov_y_deg = 45.0;
  scene.light.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.5));
  scene.light.irradiance = {3.0, 2.8, 2.6};
  scene.ambient = {0.1, 0.12, 0.15};
  scene.background = {0.2, 0.3, 0.4};
  scene.materials = {LambertMaterial{{0.8, 0.8, 0.8}}, LambertMaterial{{0.9, 0.2, 0.1}}};
  return scene;
}

TEST(ShadowRays, PlaneAloneIsLitFromAboveAndDarkFromBelow) {
  Scene scene = lit_scene();
  scene.planes.push_back({{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0});
  expect_gpu_matches_cpu(scene);
  scene.camera.position = {0.0, -2.0, 6.0};  // below: the plane faces the camera away from the light
  scene.camera.target = {0.0, -0.5, 0.0};
  expect_gpu_matches_cpu(scene);
}

TEST(ShadowRays, FinitePlanesAndMeshesShadowSpheresAndPlanes) {
  Scene scene = lit_scene();
  scene.planes.push_back({{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 0});
  scene.spheres.push_back({{-0.9, 0.6, 0.0}, 0.6, 0});
  scene.spheres.push_back({{1.1, 0.5, 0.6}, 0.5, 1});
  scene.camera.position = {0.0, 4.0, 5.0};  // from above: the spheres' lit tops in view
  Scene open = scene;
  Plane roof{{-0.8, 1.6, 0.2}, glm::normalize(glm::dvec3(0.2, 1.0, 0.1)), 1};  // over the left sphere
  roof.size = glm::dvec2(1.2, 1.0);
  scene.planes.push_back(roof);
  scene.meshes.push_back(test::pyramid({1.0, 1.15, 0.3}, 0.4, 0.5));  // floating above the right sphere
  // The roof and the pyramid cover ~2% of the frame; with their shadows on the spheres and the
  // ground the frame changes on more than 4%.
  EXPECT_GT(changed_fraction(scene, open), 0.04);
  expect_gpu_matches_cpu(scene);
}

TEST(ShadowRays, InsideASphereItsFarWallShadowsEveryPoint) {
  Scene scene = lit_scene();
  scene.spheres.push_back({{0.0, 1.0, 2.0}, 5.0, 0});  // the camera is inside
  expect_gpu_matches_cpu(scene);
  // No light gets in: every pixel is the ambient term alone, as with the light switched off.
  auto context = test::make_validated_context();
  const Image gpu = gpu::render_direct(*context, scene, kWidth, kHeight);
  const Scene dark = [&] {
    Scene s = scene;
    s.light.irradiance = glm::dvec3(0.0);
    return s;
  }();
  const Image ambient_only = cpu::render_direct_cpu(dark, kWidth, kHeight);
  double worst = 0.0;
  for (size_t i = 0; i < gpu.pixel_count(); ++i)
    worst = std::max(worst, largest(glm::dvec3(gpu.at(i)) - glm::dvec3(ambient_only.at(i))));
  EXPECT_LE(worst, 1e-6);
}

}  // namespace shadow_rays_test
}  // namespace facet
