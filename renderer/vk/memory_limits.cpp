#include "vk/memory_limits.hpp"

#include <algorithm>

namespace facet::vk {

MemoryLimits memory_limits(VkPhysicalDevice physical) {
  MemoryLimits limits;
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(physical, &memory);
  for (uint32_t i = 0; i < memory.memoryHeapCount; ++i)
    if (memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      limits.heap_bytes = std::max(limits.heap_bytes, memory.memoryHeaps[i].size);
  VkPhysicalDeviceMaintenance3Properties maintenance3{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceProperties2 properties{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
  properties.pNext = &maintenance3;
  vkGetPhysicalDeviceProperties2(physical, &properties);
  limits.allocation_bytes = maintenance3.maxMemoryAllocationSize;
  return limits;
}

}  // namespace facet::vk
