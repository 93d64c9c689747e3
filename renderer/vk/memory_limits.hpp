// What one device can hold, for refusals that name the limit: its largest device-local heap and its
// largest single allocation (maxMemoryAllocationSize; lavapipe: one 2 GiB heap, 2 GiB allocations).
#pragma once

#include <vulkan/vulkan.h>

namespace facet::vk {

struct MemoryLimits {
  VkDeviceSize heap_bytes = 0;
  VkDeviceSize allocation_bytes = 0;
};

MemoryLimits memory_limits(VkPhysicalDevice physical);

}  // namespace facet::vk
