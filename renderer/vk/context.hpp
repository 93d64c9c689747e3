// The Vulkan context: one instance, one physical device, one compute queue.
//
// Headless (no surface extensions). Device choice: lavapipe by default (facet's reference
// platform), or `device` = a name substring or an index from list_devices(). Validation
// layers are enabled by ContextOptions::validation (default: the FACET_VALIDATION
// environment variable, which every test sets); each message goes to the validation
// handler, which by default prints it on stderr, and is counted.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/pipeline_cache.hpp"

namespace facet::vk {

struct DeviceInfo {
  uint32_t index = 0;
  std::string name;
  std::string type;  // "cpu", "integrated-gpu", "discrete-gpu", "virtual-gpu", "other"
  std::string api_version;
  std::string driver;
  bool is_lavapipe = false;
};

struct ContextOptions {
  std::string device;  // empty: lavapipe if present, else device 0
  bool validation = validation_requested_by_environment();
  static bool validation_requested_by_environment();
};

// Throws facet::Error when a Vulkan call fails; `what` names the call.
void check(VkResult result, const char* what);

// Every device the loader reports; throws facet::Error if there is none.
std::vector<DeviceInfo> list_devices();

class Context {
 public:
  explicit Context(const ContextOptions& options = {});
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkDevice device() const { return device_; }
  VkPhysicalDevice physical_device() const { return physical_; }
  const DeviceInfo& info() const { return info_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }
  VkDescriptorPool descriptor_pool() const { return descriptor_pool_; }
  // The pipelines compiled on this device so far (vk/kernel.hpp).
  PipelineCache& pipelines() { return pipelines_; }
  bool validation_enabled() const { return validation_; }
  // The alignment of host memory the device can import as buffer memory (VK_EXT_external_memory_host:
  // vk::Buffer::import_host), 0 when it cannot.
  VkDeviceSize host_import_alignment() const { return host_import_alignment_; }

  // Memory type index with all `required` flags (and `preferred` ones if possible).
  uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const;

  // Records commands with `record`, submits them, waits; returns the GPU time in
  // milliseconds between a timestamp written before and after the recorded commands
  // (-1 if the queue has no timestamps).
  double submit_and_wait(const std::function<void(VkCommandBuffer)>& record);

  uint32_t validation_message_count() const { return validation_messages_; }
  void set_validation_handler(std::function<void(const std::string&)> handler);

 private:
  void release();
  static VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                              VkDebugUtilsMessageTypeFlagsEXT,
                                                              const VkDebugUtilsMessengerCallbackDataEXT*, void*);

  bool validation_ = false;
  std::atomic<uint32_t> validation_messages_ = 0;  // the layer may call back from any thread
  std::function<void(const std::string&)> validation_handler_;
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  DeviceInfo info_;
  VkPhysicalDeviceLimits limits_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  uint32_t queue_family_ = 0;
  bool has_timestamps_ = false;
  VkDeviceSize host_import_alignment_ = 0;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  VkCommandPool command_pool_ = VK_NULL_HANDLE;
  VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
  VkQueryPool timestamps_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  PipelineCache pipelines_;
};

}  // namespace facet::vk
