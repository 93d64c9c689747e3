// The direct pass specialises its pipeline from gpu::plan_diffraction before the preintegrated tables are
// read (so the compile runs beside the read): the plan's method and word layout must be the ones the
// upload binds, on every diffraction scene and method, split over several bindings too. Narrow views and
// 16 wavelengths keep the tables quick to build.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "gpu/diffraction_upload.hpp"
#include "gpu/direct_pass.hpp"
#include "scene/scene_loader.hpp"
#include "support/vulkan_fixture.hpp"

namespace facet {
namespace diffraction_plan_test {

using diffraction::DiffractionMethod;

// What the upload bound against the plan made beforehand from the same inputs.
void expect_upload_follows(vk::Context& context, const Scene& scene, const gpu::RenderMethod& method) {
  const gpu::DiffractionPlan plan = gpu::plan_diffraction(context, scene, method.diffraction);
  const gpu::DirectPass pass(context, scene, method);
  const gpu::DiffractionBuffers& bound = pass.diffraction();
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
    scene.camera.fov_y_deg = 4.0;
    for (const DiffractionMethod m :
         {DiffractionMethod::Spectral, DiffractionMethod::Orders, DiffractionMethod::Preintegrated}) {
      SCOPED_TRACE(std::string(name) + " " + diffraction::diffraction_method_name(m));
      gpu::RenderMethod method;
      method.diffraction.method = m;
      method.diffraction.wavelengths = 16;
      expect_upload_follows(*context, scene, method);
      if (m != DiffractionMethod::Preintegrated) continue;
      // Bindings of a third of the tables: split over three or four.
      const std::uint64_t words = gpu::plan_diffraction(*context, scene, method.diffraction).fast.preintegrated_word_count;
      ASSERT_GT(words, 0u);
      method.diffraction.preintegrated_binding_bytes = sizeof(std::uint32_t) * (words / 3 + 1);
      const gpu::DiffractionPlan split = gpu::plan_diffraction(*context, scene, method.diffraction);
      EXPECT_GE(split.preintegrated_slices.count, 3u);
      expect_upload_follows(*context, scene, method);
    }
  }
}

}  // namespace diffraction_plan_test
}  // namespace facet
