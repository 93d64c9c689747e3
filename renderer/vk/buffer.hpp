// A buffer on the device, with upload and readback, bound as a storage or uniform buffer or as a
// uniform texel buffer (vk::BufferKind).
//
// Host-visible memory is mapped directly (lavapipe and integrated GPUs); on a device whose
// storage memory is not host-visible, upload and download go through a staging buffer.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include <vulkan/vulkan.h>

#include "vk/context.hpp"

namespace facet::vk {

// How a shader reads a buffer binding. lavapipe 22.3 loads a storage buffer one invocation and one
// component at a time (a branch each) unless the address is a constant and the code is outside any
// branch or loop: ~12 ns per float per invocation, 15x a uniform buffer's or a texel fetch's vector
// gather (docs/render_speed.md). Read-only data is therefore better bound as
//   Uniform   a uniform buffer (at most maxUniformBufferRange bytes, 64 KiB on lavapipe), or
//   Texels    a uniform texel buffer (usamplerBuffer) of R32UI, RG32UI or RGBA32UI texels as wide as
//             the buffer's elements (Buffer::texel_bytes), of any size.
// and data a kernel writes that may exceed maxStorageBufferRange (128 MiB on lavapipe) as
//   StorageTexels  a storage texel buffer (uimageBuffer) of the same texels, up to
//                  maxTexelBufferElements of them (2^27 on lavapipe).
enum class BufferKind : uint32_t { Storage, Uniform, Texels, StorageTexels };

class Buffer {
 public:
  Buffer(Context& context, VkDeviceSize bytes);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&&) = delete;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  // Creates a buffer of `count` elements of T, not initialised (at least one element of storage, so
  // that empty arrays can still be bound). Its texels are one element of 4 or 8 bytes, else 16 bytes.
  template <class T>
  static Buffer of(Context& context, std::size_t count) {
    Buffer buffer(context, sizeof(T) * std::max<std::size_t>(count, 1));
    buffer.texel_bytes_ = sizeof(T) == 4 || sizeof(T) == 8 ? sizeof(T) : 16;
    return buffer;
  }
  // Creates a buffer holding `items`, as `of`.
  template <class T>
  static Buffer from(Context& context, std::span<const T> items) {
    Buffer buffer = of<T>(context, items.size());
    if (!items.empty()) buffer.upload(items.data(), items.size_bytes());
    return buffer;
  }
  // A host-visible buffer to fill through mapped() and copy_from into another.
  static Buffer staging(Context& context, VkDeviceSize bytes);
  // A buffer of `bytes` whose memory is the host's at `host` (VK_EXT_external_memory_host): nothing is
  // allocated or copied. `host` must be aligned to context.host_import_alignment() (nonzero) and span
  // `bytes` rounded up to it; `owner` keeps it alive until the buffer is gone. Texels as `of` with
  // elements of texel_bytes.
  static Buffer import_host(Context& context, void* host, VkDeviceSize bytes, VkDeviceSize texel_bytes,
                            std::shared_ptr<const void> owner);

  void upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  void download(void* data, VkDeviceSize bytes, VkDeviceSize offset = 0) const;
  // Copies `bytes` of `source` from source_offset to this buffer at offset, on the device.
  void copy_from(const Buffer& source, VkDeviceSize bytes, VkDeviceSize source_offset, VkDeviceSize offset = 0);
  // The buffer's memory, mapped on the host: write to it directly instead of uploading a copy. Null
  // when the memory is not host-visible.
  void* mapped() const { return mapped_; }
  // Whether the mapped memory is also host-cached: reading it back costs what host memory does (not
  // so for write-combined memory).
  bool host_cached() const { return host_cached_; }

  VkBuffer handle() const { return buffer_; }
  // A view of the whole buffer as texels of texel_bytes() (R32UI, RG32UI or RGBA32UI; made on first use,
  // kept with the buffer).
  VkBufferView texel_view() const;
  VkDeviceSize texel_bytes() const { return texel_bytes_; }
  VkDeviceSize size() const { return size_; }

 private:
  // The VkBuffer alone (no memory yet), `external` chained to its creation if not null.
  Buffer(Context& context, VkDeviceSize bytes, VkBufferUsageFlags usage,
         const VkExternalMemoryBufferCreateInfo* external);
  Buffer(Context& context, VkDeviceSize bytes, VkBufferUsageFlags usage, bool host_visible);
  Buffer(Context& context, VkDeviceSize bytes, void* host, std::shared_ptr<const void> owner);
  void bind(const VkMemoryAllocateInfo& allocation);  // allocates memory_ and binds it to buffer_
  void copy(VkBuffer from, VkBuffer to, VkDeviceSize bytes, VkDeviceSize from_offset, VkDeviceSize to_offset) const;

  Context* context_;
  VkDeviceSize size_ = 0;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  void* mapped_ = nullptr;  // null when the memory is not host-visible
  bool host_cached_ = false;
  VkDeviceSize texel_bytes_ = 16;
  mutable VkBufferView texel_view_ = VK_NULL_HANDLE;
  std::shared_ptr<const void> host_owner_;  // imported memory's owner (import_host), released after it
};

}  // namespace facet::vk
