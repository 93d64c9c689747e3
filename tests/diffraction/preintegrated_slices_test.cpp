// Preintegrated tables larger than one texel binding (issue 20): the words split over the render
// pass's word bindings so that every cell lies whole in one (gpu/preintegrated_slices.hpp), a split
// frame equal to the unsplit one, and tables past the device's memory refused in one line.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <variant>

#include "common/error.hpp"
#include "common/format_mib.hpp"
#include "diffraction_cases.hpp"
#include "gpu/diffraction_upload.hpp"
#include "gpu/direct_pass.hpp"
#include "gpu/render_layout.hpp"
#include "scene/scene_loader.hpp"
#include "support/vulkan_fixture.hpp"
#include "vk/memory_limits.hpp"

namespace facet {
namespace preintegrated_slices_test {

// Every cell start c (its words are [c, c + overlap)) must find all its words in binding c / S,
// each binding at most binding_words long, the bindings together covering every word.
void expect_cells_whole(std::uint64_t words, std::uint64_t overlap, std::uint64_t binding_words) {
  const gpu::PreintegratedSlices s = gpu::slice_preintegrated_words(words, overlap, binding_words);
  ASSERT_EQ(s.ranges.size(), s.count);
  ASSERT_LE(s.count, static_cast<std::uint32_t>(FACET_RENDER_PREINTEGRATED_SLICES));
  EXPECT_EQ(s.ranges.front().first, 0u);
  EXPECT_EQ(s.ranges.back().second, words);
  for (const auto& [begin, end] : s.ranges) EXPECT_LE(end - begin, binding_words);
  for (std::uint64_t c = 0; c + overlap <= words; ++c) {
    const std::uint64_t j = s.count == 1 ? 0 : c / s.slice_words;
    ASSERT_LT(j, s.count) << c;
    EXPECT_LE(s.ranges[j].first, c) << c;
    EXPECT_GE(s.ranges[j].second, c + overlap) << c;
  }
}

TEST(PreintegratedSlices, EveryCellLiesWholeInOneBinding) {
  expect_cells_whole(1000, 37, 1000);  // fits: one binding
  expect_cells_whole(1000, 37, 999);   // two
  expect_cells_whole(1000, 37, 300);   // four
  expect_cells_whole(1000, 1, 251);
  const gpu::PreintegratedSlices one = gpu::slice_preintegrated_words(1000, 37, 1000);
  EXPECT_EQ(one.count, 1u);
}

TEST(PreintegratedSlices, MoreThanTheBindingsHoldIsRefusedWithOneLine) {
  try {
    gpu::slice_preintegrated_words(1000, 37, 260);  // 4 slices of 223 words hold 892
    FAIL() << "accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("4 texel bindings"), std::string::npos) << message;
  }
}

constexpr int kSize = 48;

// The plate with its tables split over three bindings renders the unsplit frame: the same words
// reach the same arithmetic, only from another binding. A narrow view and 16 wavelengths keep the
// tables quick to build.
TEST(PreintegratedSlices, SplitTablesRenderTheUnsplitFrame) {
  auto context = test::make_validated_context();
  Scene scene = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/diffraction_plate.json");
  scene.camera.fov_y_deg = 20.0;
  gpu::RenderMethod method;
  method.diffraction.method = diffraction::DiffractionMethod::Preintegrated;
  method.diffraction.wavelengths = 16;
  gpu::DirectPass whole(*context, scene, method);
  ASSERT_EQ(whole.diffraction().preintegrated_slices.count, 1u);
  const std::uint64_t bytes = whole.diffraction().preintegrated_words[0].size();
  const Image unsplit = whole.render(scene.camera, kSize, kSize);

  method.diffraction.preintegrated_binding_bytes = bytes / 2;  // S < half the words: three slices
  gpu::DirectPass split(*context, scene, method);
  ASSERT_EQ(split.diffraction().preintegrated_slices.count, 3u);
  const Image image = split.render(scene.camera, kSize, kSize);
  double peak = 0.0;
  for (size_t i = 0; i < image.pixel_count(); ++i)
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(image.at(i)[c], unsplit.at(i)[c]) << i;
      peak = std::max(peak, static_cast<double>(unsplit.at(i)[c]));
    }
  EXPECT_GT(peak, 0.05);  // the orders show
}

// A coherence of 60 um on a sphere (every direction pair) asks for tables of tens of GiB: refused
// before they are built, in one line naming their size and the device memory they may take.
TEST(PreintegratedSlices, TablesPastDeviceMemoryAreRefusedWithOneLine) {
  auto context = test::make_validated_context();
  Scene scene = load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes/diffraction_plate.json");
  auto& material = std::get<DiffractionMaterial>(scene.materials[0]);
  material.grating = std::make_shared<diffraction::Grating>(test::grating(
      R"({"type":"sinusoid","period_nm":1600,"amplitude_nm":100,"size_um":64,"samples":256,"coherence_um":60})"));
  scene.planes.clear();
  Sphere sphere;
  sphere.radius = 0.5;
  sphere.material = 0;
  scene.spheres = {sphere};
  diffraction::DiffractionSettings settings;
  settings.method = diffraction::DiffractionMethod::Preintegrated;
  try {
    gpu::upload_diffraction(*context, scene, settings);
    FAIL() << "accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_NE(message.find("'grating'"), std::string::npos) << message;
    EXPECT_NE(message.find("of device memory"), std::string::npos) << message;
    const std::uint64_t heap = vk::memory_limits(context->physical_device()).heap_bytes;  // lavapipe: 2 GiB
    EXPECT_NE(message.find(format_mib(heap)), std::string::npos) << message;
  }
}

}  // namespace preintegrated_slices_test
}  // namespace facet
