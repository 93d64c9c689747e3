// The Vulkan runtime on the test device (lavapipe in CI), with validation on.
#include <array>
#include <cstring>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "common/error.hpp"
#include "scale_add.spv.h"
#include "support/vulkan_fixture.hpp"
#include "vk/buffer.hpp"
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

TEST(VkRuntime, BufferBeyondTheStorageRangeIsRefused) {
  auto context = test::make_validated_context();
  const VkDeviceSize range = context->limits().maxStorageBufferRange;
  if (range >= (VkDeviceSize(1) << 31)) GTEST_SKIP() << "device storage range too large to exceed cheaply";
  vk::Buffer big(*context, range + 256);
  vk::Buffer small(*context, 256);
  vk::Kernel kernel(*context, {.name = "scale_add", .spirv = scale_add_spv, .buffer_count = 2,
                               .push_constant_bytes = 8, .specialization = {}});
  const std::array<const vk::Buffer*, 2> bindings = {&big, &small};
  uint64_t push = 0;
  EXPECT_THROW(kernel.dispatch(bindings, &push, {1, 1, 1}), Error);
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
