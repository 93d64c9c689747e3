#include "vk/storage_image.hpp"

#include <cstring>

#include "common/error.hpp"
#include "vk/buffer.hpp"

namespace facet::vk {

namespace {
constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkImageSubresourceRange kColour{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};

void record_transition(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                       VkAccessFlags src_access, VkAccessFlags dst_access, VkPipelineStageFlags src_stage,
                       VkPipelineStageFlags dst_stage) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = src_access;
  barrier.dstAccessMask = dst_access;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = kColour;
  vkCmdPipelineBarrier(cmd, src_stage, dst_stage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}
}  // namespace

StorageImage::StorageImage(Context& context, uint32_t width, uint32_t height)
    : context_(&context), width_(width), height_(height) {
  const auto& limits = context.limits();
  if (width == 0 || height == 0 || width > limits.maxImageDimension2D || height > limits.maxImageDimension2D)
    throw Error("a storage image of " + std::to_string(width) + "x" + std::to_string(height) +
                " exceeds the device's 2D image limit of " + std::to_string(limits.maxImageDimension2D));
  VkDevice device = context.device();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = kFormat;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  check(vkCreateImage(device, &info, nullptr, &image_), "vkCreateImage");
  try {
    VkMemoryRequirements needs;
    vkGetImageMemoryRequirements(device, image_, &needs);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = needs.size;
    alloc.memoryTypeIndex = context.memory_type(needs.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, 0);
    check(vkAllocateMemory(device, &alloc, nullptr, &memory_), "vkAllocateMemory");
    check(vkBindImageMemory(device, image_, memory_, 0), "vkBindImageMemory");
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = kFormat;
    view.subresourceRange = kColour;
    check(vkCreateImageView(device, &view, nullptr, &view_), "vkCreateImageView");
    // UNDEFINED -> GENERAL, the layout shaders use; copies move it to a transfer layout and back.
    context.submit_and_wait([&](VkCommandBuffer cmd) {
      record_transition(cmd, image_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, 0,
                        VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT,
                        VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    });
  } catch (...) {
    if (view_) vkDestroyImageView(device, view_, nullptr);
    if (memory_) vkFreeMemory(device, memory_, nullptr);
    vkDestroyImage(device, image_, nullptr);
    throw;
  }
}

StorageImage::~StorageImage() {
  VkDevice device = context_->device();
  vkDestroyImageView(device, view_, nullptr);
  vkDestroyImage(device, image_, nullptr);
  vkFreeMemory(device, memory_, nullptr);
}

void StorageImage::copy(bool to_image, VkBuffer staging) const {
  const VkImageLayout transfer_layout =
      to_image ? VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL : VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  context_->submit_and_wait([&](VkCommandBuffer cmd) {
    // GENERAL -> the transfer's optimal layout -> GENERAL again, with the copy's writes made
    // visible to later shaders (upload) or to the host (download).
    const VkAccessFlags transfer_access = to_image ? VK_ACCESS_TRANSFER_WRITE_BIT : VK_ACCESS_TRANSFER_READ_BIT;
    record_transition(cmd, image_, VK_IMAGE_LAYOUT_GENERAL, transfer_layout, VK_ACCESS_SHADER_WRITE_BIT,
                      transfer_access, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width_, height_, 1};
    if (to_image)
      vkCmdCopyBufferToImage(cmd, staging, image_, transfer_layout, 1, &region);
    else
      vkCmdCopyImageToBuffer(cmd, image_, transfer_layout, staging, 1, &region);
    record_transition(cmd, image_, transfer_layout, VK_IMAGE_LAYOUT_GENERAL, transfer_access,
                      VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_HOST_READ_BIT,
                      VK_PIPELINE_STAGE_TRANSFER_BIT,
                      VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT);
  });
}

void StorageImage::upload(const glm::vec4* texels) {
  const VkDeviceSize bytes = sizeof(glm::vec4) * static_cast<VkDeviceSize>(width_) * height_;
  Buffer staging(*context_, bytes);
  staging.upload(texels, bytes);
  copy(true, staging.handle());
}

void StorageImage::download(glm::vec4* texels) const {
  const VkDeviceSize bytes = sizeof(glm::vec4) * static_cast<VkDeviceSize>(width_) * height_;
  Buffer staging(*context_, bytes);
  copy(false, staging.handle());
  staging.download(texels, bytes);
}

}  // namespace facet::vk
