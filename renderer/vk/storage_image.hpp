// A 2D RGBA32F storage image on the device (layout GENERAL between operations), with upload and
// readback through a staging buffer. Shaders declare it `layout(rgba32f) uniform image2D`
// (lavapipe cannot read storage images without a format qualifier).
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "vk/context.hpp"

namespace facet::vk {

class StorageImage {
 public:
  StorageImage(Context& context, uint32_t width, uint32_t height);
  ~StorageImage();
  StorageImage(const StorageImage&) = delete;
  StorageImage& operator=(const StorageImage&) = delete;

  // `texels`: width * height RGBA texels, row-major, top row first.
  void upload(const glm::vec4* texels);
  void download(glm::vec4* texels) const;

  VkImageView view() const { return view_; }
  uint32_t width() const { return width_; }
  uint32_t height() const { return height_; }

 private:
  void copy(bool to_image, VkBuffer staging) const;

  Context* context_;
  uint32_t width_, height_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

}  // namespace facet::vk
