// A storage buffer on the device, with upload and readback.
//
// Host-visible memory is mapped directly (lavapipe and integrated GPUs); on a device whose
// storage memory is not host-visible, upload and download go through a staging buffer.
#pragma once

#include <cstdint>
#include <span>

#include <vulkan/vulkan.h>

#include "vk/context.hpp"

namespace facet::vk {

class Buffer {
 public:
  Buffer(Context& context, VkDeviceSize bytes);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&&) = delete;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // Creates a buffer holding `items` (at least one element of storage, so that empty
  // arrays can still be bound).
  template <class T>
  static Buffer from(Context& context, std::span<const T> items) {
    Buffer buffer(context, sizeof(T) * (items.empty() ? 1 : items.size()));
    if (!items.empty()) buffer.upload(items.data(), items.size_bytes());
    return buffer;
  }

  void upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  void download(void* data, VkDeviceSize bytes, VkDeviceSize offset = 0) const;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }

 private:
  Buffer(Context& context, VkDeviceSize bytes, VkBufferUsageFlags usage, bool host_visible);
  void copy(VkBuffer from, VkBuffer to, VkDeviceSize bytes, VkDeviceSize from_offset, VkDeviceSize to_offset) const;

  Context* context_;
  VkDeviceSize size_ = 0;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;  // null when the memory is not host-visible
};

}  // namespace facet::vk
