// A buffer on the device, with upload and readback, bound as a storage or uniform buffer or as a
// uniform texel buffer (vk::BufferKind).
//
// Host-visible memory is mapped directly (lavapipe and integrated GPUs); on a device whose
// storage memory is not host-visible, upload and download go through a staging buffer.
#pragma once

#include <cstdint>
#include <span>

#include <vulkan/vulkan.h>

#include "vk/context.hpp"

namespace facet::vk {

// How a shader reads a buffer binding. lavapipe 22.3 loads a storage buffer one invocation and one
// component at a time (a branch each) unless the address is a constant and the code is outside any
// branch or loop: ~12 ns per float per invocation, 15x a uniform buffer's or a texel fetch's vector
// gather (docs/render_speed.md). Read-only data is therefore better bound as
//   Uniform   a uniform buffer (at most maxUniformBufferRange bytes, 64 KiB on lavapipe), or
//   Texels    a uniform texel buffer of RGBA32UI texels (usamplerBuffer), of any size.
enum class BufferKind : uint32_t { Storage, Uniform, Texels };

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
  // A view of the whole buffer as RGBA32UI texels (made on first use, kept with the buffer).
  VkBufferView texel_view() const;
  VkDeviceSize size() const { return size_; }

 private:
  Buffer(Context& context, VkDeviceSize bytes, VkBufferUsageFlags usage, bool host_visible);
  void copy(VkBuffer from, VkBuffer to, VkDeviceSize bytes, VkDeviceSize from_offset, VkDeviceSize to_offset) const;

  Context* context_;
  VkDeviceSize size_ = 0;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;  // null when the memory is not host-visible
  mutable VkBufferView texel_view_ = VK_NULL_HANDLE;
};

}  // namespace facet::vk
