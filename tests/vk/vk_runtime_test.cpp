// The Vulkan runtime on the test device (lavapipe in CI), with validation on.
#include <array>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "image_gradient.spv.h"
#include "scale_add.spv.h"
#include "support/vulkan_fixture.hpp"
#include "vk/buffer.hpp"
#include "vk/driver_selection.hpp"
#include "vk/kernel.hpp"

namespace facet {
namespace {

TEST(VkRuntime, ListsAtLeastOneDeviceAndPicksLavapipeByDefault) {
  auto devices = vk::list_devices();
  ASSERT_FALSE(devices.empty());
  auto context = test::make_validated_context();
  bool any_lavapipe = false;
  for (const auto& d : devices) any_lavapipe |= d.is_lavapipe;
  if (any_lavapipe) {
    EXPECT_TRUE(context->info().is_lavapipe);
  }
  EXPECT_TRUE(context->validation_enabled());
}

TEST(VkRuntime, UnknownDeviceIsAClearError) {
  vk::ContextOptions options;
  options.device = "no-such-gpu-anywhere";
  EXPECT_THROW({ vk::Context context(options); }, Error);
  options.device = "99";
  EXPECT_THROW({ vk::Context context(options); }, Error);
}

TEST(VkRuntime, BufferRoundTrip) {
  auto context = test::make_validated_context();
  std::vector<float> values(1000);
  std::iota(values.begin(), values.end(), -3.5f);
  auto buffer = vk::Buffer::from(*context, std::span<const float>(values));
  std::vector<float> back(values.size());
  buffer.download(back.data(), back.size() * sizeof(float));
  EXPECT_EQ(values, back);
}

// A staging buffer filled through its mapping and copied on the device into part of another buffer
// (the path of tables too large for one binding, or of device memory the host cannot see).
TEST(VkRuntime, StagingCopyLandsAtTheOffset) {
  auto context = test::make_validated_context();
  vk::Buffer staging = vk::Buffer::staging(*context, 400 * sizeof(float));
  ASSERT_NE(staging.mapped(), nullptr);
  auto* source = static_cast<float*>(staging.mapped());
  std::iota(source, source + 400, 1.0f);
  std::vector<float> zeros(300, 0.0f);
  auto buffer = vk::Buffer::from(*context, std::span<const float>(zeros));
  buffer.copy_from(staging, 200 * sizeof(float), 100 * sizeof(float), 50 * sizeof(float));  // values 101..300
  std::vector<float> back(300);
  buffer.download(back.data(), back.size() * sizeof(float));
  for (int i = 0; i < 300; ++i) EXPECT_EQ(back[i], i >= 50 && i < 250 ? i + 51.0f : 0.0f) << i;
  EXPECT_THROW(buffer.copy_from(staging, 300 * sizeof(float), 200 * sizeof(float)), Error);  // past the source
}

// Host memory imported as a buffer's memory (the table cache's mapped files): the device reads the
// host's bytes where they are, and the buffer keeps their owner alive until it is gone.
TEST(VkRuntime, ImportedHostMemoryIsReadByTheDevice) {
  auto context = test::make_validated_context();
  const VkDeviceSize alignment = context->host_import_alignment();
  if (alignment == 0) GTEST_SKIP() << "the device does not import host memory";
  const std::size_t count = 3000;  // 12000 bytes: not a multiple of the alignment (the allocation rounds up)
  const std::size_t span = (count * sizeof(float) + alignment - 1) / alignment * alignment;
  auto* host = static_cast<float*>(std::aligned_alloc(alignment, span));
  ASSERT_NE(host, nullptr);
  std::iota(host, host + count, 0.5f);
  std::weak_ptr<void> watch;
  std::vector<float> back(count);
  {
    std::shared_ptr<void> owner(host, &std::free);
    watch = owner;
    vk::Buffer imported = vk::Buffer::import_host(*context, host, count * sizeof(float), sizeof(float), std::move(owner));
    EXPECT_EQ(imported.mapped(), host);
    EXPECT_FALSE(watch.expired());
    std::vector<float> zeros(count, 0.0f);
    auto copy = vk::Buffer::from(*context, std::span<const float>(zeros));
    copy.copy_from(imported, count * sizeof(float), 0);  // on the device
    copy.download(back.data(), back.size() * sizeof(float));
  }
  EXPECT_TRUE(watch.expired());  // released with the buffer
  for (std::size_t i = 0; i < count; ++i) ASSERT_EQ(back[i], i + 0.5f) << i;
}

// With no device named, the loader is given lavapipe's driver alone, unless the user steers its drivers;
// the device chosen is the one the full list gives by default.
TEST(VkRuntime, LavapipeDriverAloneWhenNoDeviceIsNamed) {
  const char* kSteering[] = {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES", "VK_LOADER_DRIVERS_SELECT",
                             "VK_LOADER_DRIVERS_DISABLE"};
  for (const char* name : kSteering) ASSERT_EQ(std::getenv(name), nullptr) << name << " is set for the tests";
  bool any_lavapipe = false;
  for (const auto& d : vk::list_devices()) any_lavapipe |= d.is_lavapipe;
  if (!any_lavapipe) GTEST_SKIP() << "no lavapipe device";
  ::setenv("VK_LOADER_DRIVERS_SELECT", "*", 1);  // the user's choice stands
  vk::select_lavapipe_driver_only();
  EXPECT_FALSE(vk::lavapipe_driver_selected());
  EXPECT_EQ(std::getenv("VK_DRIVER_FILES"), nullptr);
  ::unsetenv("VK_LOADER_DRIVERS_SELECT");
  vk::select_lavapipe_driver_only();
  ASSERT_TRUE(vk::lavapipe_driver_selected());
  ASSERT_NE(std::getenv("VK_DRIVER_FILES"), nullptr);
  EXPECT_NE(std::string(std::getenv("VK_DRIVER_FILES")).find("lvp_icd"), std::string::npos);
  {
    auto context = test::make_validated_context();
    EXPECT_TRUE(context->info().is_lavapipe);
    EXPECT_EQ(vk::list_devices().size(), 1u);  // the loader now lists lavapipe alone
  }
  vk::select_every_driver();
  EXPECT_FALSE(vk::lavapipe_driver_selected());
  EXPECT_EQ(std::getenv("VK_DRIVER_FILES"), nullptr);
}

TEST(VkRuntime, KernelAppliesSpecializationAndPushConstants) {
  auto context = test::make_validated_context();
  const uint32_t count = 1000;  // not a multiple of the workgroup size: the guard matters
  std::vector<float> input(count);
  std::iota(input.begin(), input.end(), 0.0f);
  auto in = vk::Buffer::from(*context, std::span<const float>(input));
  vk::Buffer out(*context, count * sizeof(float));
  float scale = 2.5f;
  uint32_t scale_bits;
  std::memcpy(&scale_bits, &scale, sizeof scale_bits);
  vk::Kernel kernel(*context, {.name = "scale_add",
                               .spirv = scale_add_spv,
                               .buffer_count = 2,
                               .push_constant_bytes = 8,
                               .specialization = {{0, scale_bits}}});
  struct {
    float offset;
    uint32_t count;
  } push{-1.0f, count};
  const std::array<const vk::Buffer*, 2> bindings = {&in, &out};
  double gpu_ms = kernel.dispatch(bindings, &push, {(count + 63) / 64, 1, 1});
  EXPECT_GE(gpu_ms, 0.0);
  std::vector<float> result(count);
  out.download(result.data(), count * sizeof(float));
  for (uint32_t i = 0; i < count; ++i) ASSERT_EQ(result[i], input[i] * 2.5f - 1.0f) << i;
  EXPECT_EQ(context->validation_message_count(), 0u);
}

// Kernels with the same module and specialization share one compiled pipeline; another
// specialization compiles its own, and each kernel computes with its own constant.
TEST(VkRuntime, KernelsShareCompiledPipelinesPerSpecialization) {
  auto context = test::make_validated_context();
  const uint32_t count = 100;
  std::vector<float> input(count, 4.0f);
  auto in = vk::Buffer::from(*context, std::span<const float>(input));
  vk::Buffer out(*context, count * sizeof(float));
  const std::array<const vk::Buffer*, 2> bindings = {&in, &out};
  struct {
    float offset;
    uint32_t count;
  } push{0.0f, count};
  auto scaled_by = [&](float scale) {
    uint32_t bits;
    std::memcpy(&bits, &scale, sizeof bits);
    return vk::KernelDesc{.name = "scale_add",
                          .spirv = scale_add_spv,
                          .buffer_count = 2,
                          .push_constant_bytes = 8,
                          .specialization = {{0, bits}}};
  };
  const std::size_t before = context->pipelines().size();
  auto first_of = [&](vk::Kernel& kernel) {
    kernel.dispatch(bindings, &push, {(count + 63) / 64, 1, 1});
    float first;
    out.download(&first, sizeof first);
    return first;
  };
  vk::Kernel twice(*context, scaled_by(2.0f));
  vk::Kernel twice_again(*context, scaled_by(2.0f));
  EXPECT_EQ(context->pipelines().size(), before + 1);
  vk::Kernel thrice(*context, scaled_by(3.0f));
  EXPECT_EQ(context->pipelines().size(), before + 2);
  EXPECT_EQ(first_of(twice_again), 8.0f);
  EXPECT_EQ(first_of(thrice), 12.0f);
  EXPECT_EQ(first_of(twice), 8.0f);
  EXPECT_EQ(context->validation_message_count(), 0u);
}

TEST(VkRuntime, BufferBeyondTheStorageRangeIsRefused) {
  auto context = test::make_validated_context();
  const VkDeviceSize range = context->limits().maxStorageBufferRange;
  if (range >= (VkDeviceSize(1) << 31)) GTEST_SKIP() << "device storage range too large to exceed cheaply";
  vk::Buffer big(*context, range + 256);
  vk::Buffer small(*context, 256);
  vk::Kernel kernel(
      *context,
      {.name = "scale_add", .spirv = scale_add_spv, .buffer_count = 2, .push_constant_bytes = 8, .specialization = {}});
  const std::array<const vk::Buffer*, 2> bindings = {&big, &small};
  uint64_t push = 0;
  EXPECT_THROW(kernel.dispatch(bindings, &push, {1, 1, 1}), Error);
}

TEST(VkRuntime, StorageImagesRoundTripThroughAKernel) {
  auto context = test::make_validated_context();
  const uint32_t w = 37, h = 21;  // not multiples of the workgroup size
  std::vector<glm::vec4> texels(w * h);
  for (uint32_t i = 0; i < texels.size(); ++i) texels[i] = glm::vec4(i, -0.5f * i, 0.25f, 1.0f);
  vk::StorageImage source(*context, w, h), target(*context, w, h);
  source.upload(texels.data());
  glm::uvec2 size(w, h);
  auto size_buffer = vk::Buffer::from(*context, std::span<const glm::uvec2>(&size, 1));
  vk::Kernel kernel(*context, {.name = "image_gradient",
                               .spirv = image_gradient_spv,
                               .buffer_count = 1,
                               .push_constant_bytes = 0,
                               .image_count = 2,
                               .specialization = {}});
  const std::array<const vk::Buffer*, 1> buffers = {&size_buffer};
  const std::array<const vk::StorageImage*, 2> images = {&source, &target};
  kernel.dispatch(buffers, images, nullptr, {(w + 7) / 8, (h + 7) / 8, 1});
  std::vector<glm::vec4> result(w * h);
  target.download(result.data());
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      ASSERT_EQ(result[y * w + x], 2.0f * texels[y * w + x] + glm::vec4(x, y, 0.0f, 1.0f)) << x << " " << y;
  EXPECT_EQ(context->validation_message_count(), 0u);
}

TEST(VkRuntime, AbsurdImageSizeIsRefused) {
  auto context = test::make_validated_context();
  EXPECT_THROW(vk::StorageImage(*context, 1u << 30, 4), Error);
  EXPECT_THROW(vk::StorageImage(*context, 0, 4), Error);
}

// The validation layer is live: a deliberate misuse is reported through the handler.
TEST(VkRuntime, ValidationLayerReportsMisuse) {
  vk::ContextOptions options;
  options.validation = true;
  vk::Context context(options);
  int reported = 0;
  context.set_validation_handler([&](const std::string&) { ++reported; });
  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = 64;
  info.usage = 0;  // invalid: VUID-VkBufferCreateInfo-usage-requiredbitmask
  VkBuffer buffer = VK_NULL_HANDLE;
  if (vkCreateBuffer(context.device(), &info, nullptr, &buffer) == VK_SUCCESS)
    vkDestroyBuffer(context.device(), buffer, nullptr);
  EXPECT_GE(reported, 1);
  EXPECT_GE(context.validation_message_count(), 1u);
}

}  // namespace
}  // namespace facet
