#include "vk/buffer.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <utility>

#include "common/error.hpp"

namespace facet::vk {

namespace {
constexpr VkBufferUsageFlags kAnyUse =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
    VK_BUFFER_USAGE_STORAGE_TEXEL_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkMemoryPropertyFlags kMappable = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
}  // namespace

// Host allocations imported as buffer memory (import_host).
constexpr VkExternalMemoryBufferCreateInfo kHostAllocation{VK_STRUCTURE_TYPE_EXTERNAL_MEMORY_BUFFER_CREATE_INFO,
                                                           nullptr,
                                                           VK_EXTERNAL_MEMORY_HANDLE_TYPE_HOST_ALLOCATION_BIT_EXT};

Buffer::Buffer(Context& context, VkDeviceSize bytes) : Buffer(context, bytes, kAnyUse, false) {}

Buffer::Buffer(Context& context, VkDeviceSize bytes, VkBufferUsageFlags usage,
               const VkExternalMemoryBufferCreateInfo* external)
    : context_(&context), size_(bytes) {
  if (bytes == 0) throw Error("internal: a Vulkan buffer of 0 bytes was requested");
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, external};
  info.size = bytes;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(context.device(), &info, nullptr, &buffer_), "vkCreateBuffer");
}

void Buffer::bind(const VkMemoryAllocateInfo& allocation) {
  check(vkAllocateMemory(context_->device(), &allocation, nullptr, &memory_), "vkAllocateMemory");
  check(vkBindBufferMemory(context_->device(), buffer_, memory_, 0), "vkBindBufferMemory");
}

// The constructors below delegate the VkBuffer's creation: once that constructor has returned, the
// object is constructed, so if they throw, the destructor frees whatever they made.
Buffer::Buffer(Context& context, VkDeviceSize bytes, VkBufferUsageFlags usage, bool host_visible)
    : Buffer(context, bytes, usage, nullptr) {
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(context.device(), buffer_, &needs);
  const uint32_t type = host_visible
                            ? context.memory_type(needs.memoryTypeBits, kMappable, 0)
                            : context.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, kMappable);
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = needs.size;
  alloc.memoryTypeIndex = type;
  bind(alloc);
  VkPhysicalDeviceMemoryProperties memory;
  vkGetPhysicalDeviceMemoryProperties(context.physical_device(), &memory);
  const VkMemoryPropertyFlags properties = memory.memoryTypes[type].propertyFlags;
  if ((properties & kMappable) == kMappable) {
    check(vkMapMemory(context.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_), "vkMapMemory");
    host_cached_ = (properties & VK_MEMORY_PROPERTY_HOST_CACHED_BIT) != 0;
  }
}

Buffer::Buffer(Context& context, VkDeviceSize bytes, void* host, std::shared_ptr<const void> owner)
    : Buffer(context, bytes, kAnyUse, &kHostAllocation) {
  host_owner_ = std::move(owner);
  const VkDeviceSize alignment = context.host_import_alignment();
  if (alignment == 0 || reinterpret_cast<std::uintptr_t>(host) % alignment != 0)
    throw Error("internal: host memory the device cannot import");
  VkDevice device = context.device();
  VkMemoryRequirements needs;
  vkGetBufferMemoryRequirements(device, buffer_, &needs);
  auto host_properties = reinterpret_cast<PFN_vkGetMemoryHostPointerPropertiesEXT>(
      vkGetDeviceProcAddr(device, "vkGetMemoryHostPointerPropertiesEXT"));
  VkMemoryHostPointerPropertiesEXT pointer{VK_STRUCTURE_TYPE_MEMORY_HOST_POINTER_PROPERTIES_EXT};
  check(host_properties(device, VK_EXTERNAL_MEMORY_HANDLE_TYPE_HOST_ALLOCATION_BIT_EXT, host, &pointer),
        "vkGetMemoryHostPointerPropertiesEXT");
  VkImportMemoryHostPointerInfoEXT import{VK_STRUCTURE_TYPE_IMPORT_MEMORY_HOST_POINTER_INFO_EXT};
  import.handleType = VK_EXTERNAL_MEMORY_HANDLE_TYPE_HOST_ALLOCATION_BIT_EXT;
  import.pHostPointer = host;
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, &import};
  alloc.allocationSize = (std::max(needs.size, bytes) + alignment - 1) / alignment * alignment;
  alloc.memoryTypeIndex = context.memory_type(needs.memoryTypeBits & pointer.memoryTypeBits, 0, kMappable);
  bind(alloc);
  mapped_ = host;
  host_cached_ = true;  // the host's own memory
}

Buffer Buffer::import_host(Context& context, void* host, VkDeviceSize bytes, VkDeviceSize texel_bytes,
                           std::shared_ptr<const void> owner) {
  Buffer buffer(context, bytes, host, std::move(owner));
  buffer.texel_bytes_ = texel_bytes;
  return buffer;
}

Buffer Buffer::staging(Context& context, VkDeviceSize bytes) {
  return Buffer(context, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
}

Buffer::Buffer(Buffer&& other) noexcept
    : context_(other.context_),
      size_(other.size_),
      buffer_(std::exchange(other.buffer_, VK_NULL_HANDLE)),
      memory_(std::exchange(other.memory_, VK_NULL_HANDLE)),
      mapped_(std::exchange(other.mapped_, nullptr)),
      host_cached_(other.host_cached_),
      texel_bytes_(other.texel_bytes_),
      texel_view_(std::exchange(other.texel_view_, VK_NULL_HANDLE)),
      host_owner_(std::move(other.host_owner_)) {}

Buffer::~Buffer() {
  if (texel_view_) vkDestroyBufferView(context_->device(), texel_view_, nullptr);
  if (buffer_) vkDestroyBuffer(context_->device(), buffer_, nullptr);
  if (memory_) vkFreeMemory(context_->device(), memory_, nullptr);
}

VkBufferView Buffer::texel_view() const {
  if (texel_view_) return texel_view_;
  if (size_ < texel_bytes_) throw Error("internal: a texel view of a buffer smaller than one texel");
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer_;
  info.format = texel_bytes_ == 4   ? VK_FORMAT_R32_UINT
                : texel_bytes_ == 8 ? VK_FORMAT_R32G32_UINT
                                    : VK_FORMAT_R32G32B32A32_UINT;
  info.range = VK_WHOLE_SIZE;
  check(vkCreateBufferView(context_->device(), &info, nullptr, &texel_view_), "vkCreateBufferView");
  return texel_view_;
}

void Buffer::copy(VkBuffer from, VkBuffer to, VkDeviceSize bytes, VkDeviceSize from_offset,
                  VkDeviceSize to_offset) const {
  context_->submit_and_wait([&](VkCommandBuffer cmd) {
    VkBufferCopy region{from_offset, to_offset, bytes};
    vkCmdCopyBuffer(cmd, from, to, 1, &region);
  });
}

void Buffer::copy_from(const Buffer& source, VkDeviceSize bytes, VkDeviceSize source_offset, VkDeviceSize offset) {
  if (source_offset + bytes > source.size_ || offset + bytes > size_)
    throw Error("internal: a copy beyond the end of a Vulkan buffer");
  copy(source.buffer_, buffer_, bytes, source_offset, offset);
}

void Buffer::upload(const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (offset + bytes > size_) throw Error("internal: upload beyond the end of a Vulkan buffer");
  if (mapped_) {
    std::memcpy(static_cast<char*>(mapped_) + offset, data, bytes);
    return;
  }
  Buffer staging(*context_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
  std::memcpy(staging.mapped_, data, bytes);
  copy(staging.buffer_, buffer_, bytes, 0, offset);
}

void Buffer::download(void* data, VkDeviceSize bytes, VkDeviceSize offset) const {
  if (offset + bytes > size_) throw Error("internal: download beyond the end of a Vulkan buffer");
  if (mapped_) {
    std::memcpy(data, static_cast<const char*>(mapped_) + offset, bytes);
    return;
  }
  Buffer staging(*context_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
  copy(buffer_, staging.buffer_, bytes, offset, 0);
  std::memcpy(data, staging.mapped_, bytes);
}

}  // namespace facet::vk
