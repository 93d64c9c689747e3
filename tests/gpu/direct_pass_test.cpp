// The GPU Lambert pass (float, own BVH) against its CPU twin (double, Embree) on the same rays.
#include <cmath>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "cpu/direct_cpu.hpp"
#include "cpu/ray_caster.hpp"
#include "gpu/direct_pass.hpp"
#include "kernels/shared.hpp"
#include "lambert_scenes.hpp"
#include "scene/camera_frame.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace {

struct Agreement {
  double within_fraction;  // pixels whose channels all agree within the tolerance
  double max_error;        // over those pixels
};

Agreement compare(const Image& gpu, const Image& cpu, double tolerance) {
  size_t within = 0;
  double max_error = 0.0;
  for (size_t i = 0; i < gpu.pixel_count(); ++i) {
    glm::dvec3 d = glm::abs(glm::dvec3(gpu.at(i)) - glm::dvec3(cpu.at(i)));
    double e = std::max({d.x, d.y, d.z});
    if (e <= tolerance) {
      ++within;
      max_error = std::max(max_error, e);
    }
  }
  return {static_cast<double>(within) / gpu.pixel_count(), max_error};
}

// Float evaluation of the same ray differs from double by a few ulp of the ray direction and
// distance, i.e. ~1e-6 relative in the shaded value (~3 radiance units at most here): 1e-4
// absolute is a 30x margin. Pixels whose ray grazes a silhouette or a shadow edge can flip
// object or visibility between float and double; at 96x64 those are well under 1% of pixels.
constexpr double kTolerance = 1e-4;
constexpr double kMinAgreeingFraction = 0.99;

TEST(DirectPass, GpuMatchesCpuOnAnalyticScene) {
  auto context = test::make_validated_context();
  Scene scene = test::lambert_spheres_scene();
  Image gpu = gpu::render_direct(*context, scene, 96, 64, {}, nullptr, {}, 32);  // several tiles
  Image cpu = cpu::render_direct_cpu(scene, 96, 64);
  Agreement a = compare(gpu, cpu, kTolerance);
  EXPECT_GE(a.within_fraction, kMinAgreeingFraction);
  EXPECT_LE(a.max_error, kTolerance);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Every pixel is rendered once whatever the tile size: tiles of one workgroup, of partial
// workgroups (20 px), of several permuted workgroups (32 px) and of the whole frame give the same
// bits (each pixel's arithmetic does not depend on which workgroup renders it).
TEST(DirectPass, TileSizesRenderTheSameImage) {
  auto context = test::make_validated_context();
  Scene scene = test::lambert_spheres_scene();
  const Image whole = gpu::render_direct(*context, scene, 70, 45, {}, nullptr, {}, 256);
  for (int tile : {8, 20, 32}) {
    const Image tiled = gpu::render_direct(*context, scene, 70, 45, {}, nullptr, {}, tile);
    for (int y = 0; y < 45; ++y)
      for (int x = 0; x < 70; ++x) ASSERT_EQ(tiled.at(x, y), whole.at(x, y)) << tile << " " << x << "," << y;
  }
  EXPECT_THROW(gpu::DirectPass(*context, scene, gpu::RenderMethod{}, gpu::kMaxTileSize + 1), Error);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

TEST(DirectPass, GpuBvhMatchesEmbreeOnMeshes) {
  auto context = test::make_validated_context();
  Scene scene = test::lambert_spheres_scene();
  scene.spheres.clear();
  scene.meshes.push_back(test::pyramid({0.0, 0.0, 0.0}, 0.8, 1.4));
  scene.meshes.push_back(test::pyramid({1.4, 0.0, 1.0}, 0.4, 0.6));
  Image gpu = gpu::render_direct(*context, scene, 96, 64);
  Image cpu = cpu::render_direct_cpu(scene, 96, 64);
  Agreement a = compare(gpu, cpu, kTolerance);
  EXPECT_GE(a.within_fraction, kMinAgreeingFraction);
  // The pyramids must actually be visible (they cover about 7% of this frame and shadow the
  // ground): the render must differ from one without them on at least 3% of the pixels.
  Scene empty = scene;
  empty.meshes.clear();
  Agreement without = compare(gpu, cpu::render_direct_cpu(empty, 96, 64), kTolerance);
  EXPECT_LT(without.within_fraction, 0.97);
}

// A coarse mesh with smooth normals: near its silhouettes a face seen from the front has an interpolated normal
// leaning away from the viewer. Both passes shade such a hit on its face's side (ray_caster.hpp's convention);
// the GPU once turned the normal by the ray alone, lighting those hits as the mesh's inside (default.json's torus).
TEST(DirectPass, SmoothMeshNormalsKeepTheSideOfTheirFace) {
  auto context = test::make_validated_context();
  Scene scene = test::lambert_spheres_scene();
  scene.spheres.clear();
  scene.meshes.push_back(test::smooth_sphere({-0.2, 1.1, 0.0}, 1.1, 4, 5));
  constexpr int kWidth = 96, kHeight = 64;
  Image gpu = gpu::render_direct(*context, scene, kWidth, kHeight);
  Image cpu = cpu::render_direct_cpu(scene, kWidth, kHeight);
  EXPECT_GE(compare(gpu, cpu, kTolerance).within_fraction, kMinAgreeingFraction);
  EXPECT_EQ(context->validation_message_count(), 0u);
  // The hits this is about: the shading normal faces away from the camera, and the light it receives differs by
  // more than 0.05 from what the normal turned toward the camera would receive. They must be there, and agree.
  const RayCaster caster(scene);
  const CameraFrame camera = camera_frame(scene.camera, kWidth, kHeight);
  const glm::dvec3 l = scene.light.direction;
  int leaning = 0, agreeing = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const glm::dvec3 d = kernels::f64::camera_ray_direction(
          camera.forward, camera.right, camera.up, glm::dvec2(x + 0.5, y + 0.5), glm::dvec2(kWidth, kHeight));
      const auto hit = caster.intersect(camera.origin, d);
      const double cos_l = hit ? glm::dot(hit->shading_normal, l) : 0.0;
      if (!hit || glm::dot(hit->shading_normal, d) <= 0.0 ||
          std::abs(std::max(cos_l, 0.0) - std::max(-cos_l, 0.0)) <= 0.05)
        continue;
      ++leaning;
      const glm::dvec3 e = glm::abs(glm::dvec3(gpu.at(x, y)) - glm::dvec3(cpu.at(x, y)));
      if (std::max({e.x, e.y, e.z}) <= kTolerance) ++agreeing;
    }
  }
  EXPECT_GE(leaning, 20) << "the frame no longer tests what it is for";
  EXPECT_GE(agreeing, 0.9 * leaning);
}

// Every distribution, from near-mirror to near-isotropic flakes: the microflake branch of the
// shader (enabled by its specialization constant) against the double twin.
TEST(DirectPass, MicroflakeMaterialsMatchCpu) {
  auto context = test::make_validated_context();
  Scene scene = test::lambert_spheres_scene();
  scene.spheres.clear();
  const std::pair<Ndf, double> flakes[] = {{Ndf::Beckmann, 0.3},
                                           {Ndf::Ggx, 0.05},
                                           {Ndf::Ellipsoidal, 0.9},
                                           {Ndf::SphericalGaussian, 0.2},
                                           {Ndf::SphericalGaussian, 50.0}};
  for (int i = 0; i < 5; ++i) {
    scene.materials.push_back(MicroflakeMaterial{flakes[i].first, flakes[i].second, {0.9, 0.7, 0.5}});
    scene.spheres.push_back({{-2.0 + i, 0.45, 0.0}, 0.45, static_cast<uint32_t>(scene.materials.size() - 1)});
  }
  scene.planes[0].material = static_cast<uint32_t>(scene.materials.size() - 1);
  Image gpu = gpu::render_direct(*context, scene, 96, 64);
  Image cpu = cpu::render_direct_cpu(scene, 96, 64);
  // The microflake kernels agree float vs double to ~1e-6 relative (cross_section_gpu_test);
  // radiance here is at most ~10, and near-mirror GGX highlights magnify direction rounding.
  Agreement a = compare(gpu, cpu, 1e-3);
  EXPECT_GE(a.within_fraction, kMinAgreeingFraction);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

TEST(DirectPass, EmptySceneShowsBackground) {
  auto context = test::make_validated_context();
  Scene scene = test::lambert_spheres_scene();
  scene.planes.clear();
  scene.spheres.clear();
  Image gpu = gpu::render_direct(*context, scene, 16, 8);
  for (size_t i = 0; i < gpu.pixel_count(); ++i)
    ASSERT_EQ(glm::dvec3(gpu.at(i)), glm::dvec3(glm::vec3(scene.background)));
}

}  // namespace
}  // namespace facet
