// The direct pass specialises its pipeline from gpu::plan_diffraction before the preintegrated tables are
// read (so the compile runs beside the read): the plan's method and word layout must be the ones the
// upload binds, on every diffraction scene and method, split over several bindings too. Narrow views and
// 8 wavelengths keep the tables quick to build.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>

#include "gpu/diffraction_upload.hpp"
#include "gpu/render_method.hpp"
#include "scene/scene_loader.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace diffraction_plan_test {

using diffraction::DiffractionMethod;

// What the upload bound against the plan made beforehand from the same inputs.
void expect_upload_follows(vk::Context& context, const Scene& scene, const gpu::RenderMethod& method) {
  const gpu::DiffractionPlan plan = gpu::plan_diffraction(context, scene, method.diffraction);
  // What gpu::DirectPass does: its specialization from one plan, the upload from another of the same inputs.
  const gpu::DiffractionBuffers bound =
      gpu::upload_diffraction(context, gpu::plan_diffraction(context, scene, method.diffraction));
  EXPECT_EQ(bound.method, plan.method);
  const gpu::PreintegratedSlices& s = plan.preintegrated_slices;
  EXPECT_EQ(bound.preintegrated_slices.count, s.count);
  EXPECT_EQ(bound.preintegrated_slices.slice_words, s.slice_words);
  ASSERT_EQ(bound.preintegrated_slices.ranges, s.ranges);
  ASSERT_EQ(s.ranges.size(), s.count);
  EXPECT_EQ(s.ranges.back().second, plan.fast.preintegrated_word_count);
  for (std::uint32_t j = 0; j < s.count; ++j) {
    const auto& [begin, end] = s.ranges[j];
    EXPECT_EQ(bound.preintegrated_words[j].size(), std::max<std::uint64_t>(end - begin, 1) * sizeof(std::uint32_t))
        << j;
  }
}

TEST(DiffractionPlan, TheUploadBindsThePlannedMethodAndLayout) {
  auto context = test::make_validated_context();
  for (const char* name : {"diffraction_plate.json", "snake_fingers.json", "diffraction_random.json",
                           "diffraction_binary.json", "diffraction_crossed_rotated.json"}) {
    Scene scene = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes" / name);
    scene.camera.fov_y_deg = 2.0;
    for (const DiffractionMethod m :
         {DiffractionMethod::Spectral, DiffractionMethod::Orders, DiffractionMethod::Preintegrated}) {
      SCOPED_TRACE(std::string(name) + " " + diffraction::diffraction_method_name(m));
      gpu::RenderMethod method;
      method.diffraction.method = m;
      method.diffraction.wavelengths = 8;
      expect_upload_follows(*context, scene, method);
      if (m != DiffractionMethod::Preintegrated) continue;
      // Bindings of a third of the tables and one cell row: split over three.
      const gpu::DiffractionPlan whole = gpu::plan_diffraction(*context, scene, method.diffraction);
      const std::uint64_t words = whole.fast.preintegrated_word_count;
      ASSERT_GT(words, 0u);
      method.diffraction.preintegrated_binding_bytes = sizeof(std::uint32_t) * (whole.fast.cell_words + words / 3 + 1);
      EXPECT_EQ(gpu::plan_diffraction(*context, scene, method.diffraction).preintegrated_slices.count, 3u);
      expect_upload_follows(*context, scene, method);
    }
  }
}

// Under `orders` the pass compiles the spectral path in only where some grating is not restricted (not periodic,
// or its orders unresolved: F.10, F.11), as the upload marks it (fast_scalars.z = 0).
TEST(DiffractionPlan, OrdersFallBackOnlyWhereSomeGratingIsNotRestricted) {
  auto context = test::make_validated_context();
  const std::filesystem::path scenes = std::filesystem::path(FACET_SOURCE_DIR) / "scenes";
  const auto falls_back = [&](const Scene& scene, DiffractionMethod m) {
    gpu::RenderMethod method;
    method.diffraction.method = m;
    method.diffraction.wavelengths = 8;
    return gpu::orders_fall_back(gpu::plan_diffraction(*context, scene, method.diffraction));
  };
  Scene plate = load_scene(scenes / "diffraction_plate.json");
  plate.camera.fov_y_deg = 2.0;
  EXPECT_FALSE(falls_back(plate, DiffractionMethod::Orders));  // periodic, its orders resolved
  EXPECT_FALSE(falls_back(plate, DiffractionMethod::Spectral));
  EXPECT_FALSE(falls_back(plate, DiffractionMethod::Preintegrated));
  EXPECT_TRUE(falls_back(load_scene(scenes / "diffraction_random.json"), DiffractionMethod::Orders));  // F.10
  EXPECT_TRUE(falls_back(load_scene(scenes / "snake_fingers.json"), DiffractionMethod::Orders));       // F.11
  // One grating without orders among periodic ones, even unused, brings the fallback back.
  Scene mixed = load_scene(scenes / "diffraction_plate.json",
                           {R"(materials.random={"type": "diffraction", "grating": {"type": "heightmap",
                               "path": "gratings/random_heights.exr", "channel": "R", "nm_per_sample": 62.5,
                               "nm_per_unit": 1, "coherence_um": 4}, "tolerance": 0.001})"});
  mixed.camera.fov_y_deg = 2.0;
  EXPECT_TRUE(falls_back(mixed, DiffractionMethod::Orders));
  EXPECT_EQ(context->validation_message_count(), 0u);
}

}  // namespace diffraction_plan_test
}  // namespace facet
