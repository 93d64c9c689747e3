#include "vk/context.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <iostream>

#include "common/counted.hpp"
#include "common/error.hpp"
#include "vk/driver_selection.hpp"

namespace facet::vk {

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

std::string device_type_name(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return "cpu";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return "integrated-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return "discrete-gpu";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return "virtual-gpu";
    default:
      return "other";
  }
}

std::string version_string(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

DeviceInfo describe(VkPhysicalDevice physical, uint32_t index) {
  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(physical, &props);
  DeviceInfo info;
  info.index = index;
  info.name = props.properties.deviceName;
  info.type = device_type_name(props.properties.deviceType);
  info.api_version = version_string(props.properties.apiVersion);
  info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
  info.is_lavapipe = driver.driverID == VK_DRIVER_ID_MESA_LLVMPIPE;
  return info;
}

// minImportedHostPointerAlignment when the device has VK_EXT_external_memory_host, else 0.
VkDeviceSize importable_host_alignment(VkPhysicalDevice physical) {
  uint32_t count = 0;
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, nullptr);
  std::vector<VkExtensionProperties> extensions(count);
  vkEnumerateDeviceExtensionProperties(physical, nullptr, &count, extensions.data());
  const bool has = std::any_of(extensions.begin(), extensions.end(), [](const VkExtensionProperties& e) {
    return std::strcmp(e.extensionName, VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME) == 0;
  });
  if (!has) return 0;
  VkPhysicalDeviceExternalMemoryHostPropertiesEXT host{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_EXTERNAL_MEMORY_HOST_PROPERTIES_EXT};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &host};
  vkGetPhysicalDeviceProperties2(physical, &props);
  return host.minImportedHostPointerAlignment;
}

bool layer_available(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& layer : layers)
    if (std::strcmp(layer.layerName, name) == 0) return true;
  return false;
}

VkInstance create_instance(bool validation, const VkDebugUtilsMessengerCreateInfoEXT* messenger) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "facet";
  app.apiVersion = VK_API_VERSION_1_2;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  const char* extension = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
  if (validation) {
    if (!layer_available(kValidationLayer))
      throw Error(
          "Vulkan validation requested but VK_LAYER_KHRONOS_validation is not installed "
          "(Debian package vulkan-validationlayers)");
    info.enabledLayerCount = 1;
    info.ppEnabledLayerNames = &kValidationLayer;
    info.enabledExtensionCount = 1;
    info.ppEnabledExtensionNames = &extension;
    info.pNext = messenger;  // also covers instance creation and destruction
  }
  VkInstance instance = VK_NULL_HANDLE;
  VkResult result = vkCreateInstance(&info, nullptr, &instance);
  if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
    throw Error("no Vulkan driver found (install mesa-vulkan-drivers for the lavapipe CPU device)");
  check(result, "vkCreateInstance");
  return instance;
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
  uint32_t count = 0;
  check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  std::vector<VkPhysicalDevice> devices(count);
  check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
  if (devices.empty()) throw Error("no Vulkan device found (install mesa-vulkan-drivers for the lavapipe CPU device)");
  return devices;
}

// An instance with at least one device: when lavapipe's driver was selected alone
// (driver_selection.hpp) and gives none, the selection is dropped and every driver asked.
VkInstance instance_with_devices(bool validation, const VkDebugUtilsMessengerCreateInfoEXT* messenger) {
  if (lavapipe_driver_selected()) {
    try {
      VkInstance instance = create_instance(validation, messenger);
      uint32_t count = 0;
      if (vkEnumeratePhysicalDevices(instance, &count, nullptr) == VK_SUCCESS && count > 0) return instance;
      vkDestroyInstance(instance, nullptr);
    } catch (const Error&) {
    }
    select_every_driver();
  }
  return create_instance(validation, messenger);
}

uint32_t choose_device(const std::vector<DeviceInfo>& infos, const std::string& wanted) {
  if (wanted.empty()) {
    for (const auto& info : infos)
      if (info.is_lavapipe) return info.index;
    return 0;
  }
  char* end = nullptr;
  unsigned long index = std::strtoul(wanted.c_str(), &end, 10);
  if (end != wanted.c_str() && *end == '\0') {
    if (index >= infos.size())
      throw Error("--device " + wanted + ": out of range, this machine has " +
                  counted(static_cast<std::int64_t>(infos.size()), "Vulkan device") + " (see 'facet info')");
    return static_cast<uint32_t>(index);
  }
  for (const auto& info : infos)
    if (info.name.find(wanted) != std::string::npos) return info.index;
  throw Error("--device " + wanted + ": no Vulkan device has that name (see 'facet info')");
}

VkQueueFamilyProperties compute_queue_family(VkPhysicalDevice physical, uint32_t& index) {
  uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical, &count, families.data());
  for (index = 0; index < count; ++index)
    if (families[index].queueFlags & VK_QUEUE_COMPUTE_BIT) return families[index];
  throw Error("the Vulkan device has no compute queue");
}

}  // namespace

void check(VkResult result, const char* what) {
  if (result == VK_SUCCESS) return;
  if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
    throw Error(std::string(what) + " failed: out of memory (VkResult " + std::to_string(result) + ")");
  throw Error(std::string(what) + " failed (VkResult " + std::to_string(result) + ")");
}

bool ContextOptions::validation_requested_by_environment() {
  const char* value = std::getenv("FACET_VALIDATION");
  return value != nullptr && std::strcmp(value, "") != 0 && std::strcmp(value, "0") != 0;
}

std::vector<DeviceInfo> list_devices() {
  VkInstance instance = create_instance(false, nullptr);
  std::vector<DeviceInfo> infos;
  try {
    auto devices = physical_devices(instance);
    for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
  } catch (...) {
    vkDestroyInstance(instance, nullptr);
    throw;
  }
  vkDestroyInstance(instance, nullptr);
  return infos;
}

VKAPI_ATTR VkBool32 VKAPI_CALL Context::on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                              VkDebugUtilsMessageTypeFlagsEXT,
                                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                              void* user) {
  auto* self = static_cast<Context*>(user);
  ++self->validation_messages_;
  std::string message = std::string("Vulkan validation: ") + (data->pMessageIdName ? data->pMessageIdName : "") + ": " +
                        (data->pMessage ? data->pMessage : "");
  if (self->validation_handler_)
    self->validation_handler_(message);
  else
    std::cerr << message << "\n";
  return VK_FALSE;
}

void Context::set_validation_handler(std::function<void(const std::string&)> handler) {
  validation_handler_ = std::move(handler);
}

Context::Context(const ContextOptions& options) : validation_(options.validation) {
  VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messenger.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                          VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messenger.pfnUserCallback = &Context::on_validation_message;
  messenger.pUserData = this;
  instance_ = instance_with_devices(validation_, &messenger);
  try {
    if (validation_) {
      auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
      check(create(instance_, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }
    auto devices = physical_devices(instance_);
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], i));
    uint32_t chosen = choose_device(infos, options.device);
    physical_ = devices[chosen];
    info_ = infos[chosen];
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(physical_, &props);
    limits_ = props.limits;
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
    has_timestamps_ = compute_queue_family(physical_, queue_family_).timestampValidBits > 0;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = queue_family_;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue;
    // Host memory imported as buffer memory: the table cache's files are bound where they are mapped.
    const char* host_import = VK_EXT_EXTERNAL_MEMORY_HOST_EXTENSION_NAME;
    host_import_alignment_ = importable_host_alignment(physical_);
    if (host_import_alignment_ > 0) {
      device_info.enabledExtensionCount = 1;
      device_info.ppEnabledExtensionNames = &host_import;
    }
    check(vkCreateDevice(physical_, &device_info, nullptr, &device_), "vkCreateDevice");
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = queue_family_;
    check(vkCreateCommandPool(device_, &pool, nullptr, &command_pool_), "vkCreateCommandPool");

    VkDescriptorPoolSize sizes[] = {{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 256},
                                    {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 64},
                                    {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 64},
                                    {VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 256},
                                    {VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, 16}};
    VkDescriptorPoolCreateInfo descriptors{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    descriptors.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    descriptors.maxSets = 32;
    descriptors.poolSizeCount = static_cast<uint32_t>(std::size(sizes));
    descriptors.pPoolSizes = sizes;
    check(vkCreateDescriptorPool(device_, &descriptors, nullptr, &descriptor_pool_), "vkCreateDescriptorPool");

    VkQueryPoolCreateInfo query{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    query.queryType = VK_QUERY_TYPE_TIMESTAMP;
    query.queryCount = 2;
    check(vkCreateQueryPool(device_, &query, nullptr, &timestamps_), "vkCreateQueryPool");

    VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(device_, &fence, nullptr, &fence_), "vkCreateFence");
  } catch (...) {
    release();
    throw;
  }
}

Context::~Context() { release(); }

void Context::release() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    pipelines_.clear();
    if (fence_) vkDestroyFence(device_, fence_, nullptr);
    if (timestamps_) vkDestroyQueryPool(device_, timestamps_, nullptr);
    if (descriptor_pool_) vkDestroyDescriptorPool(device_, descriptor_pool_, nullptr);
    if (command_pool_) vkDestroyCommandPool(device_, command_pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
    device_ = VK_NULL_HANDLE;
  }
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    destroy(instance_, messenger_, nullptr);
    messenger_ = VK_NULL_HANDLE;
  }
  if (instance_) {
    vkDestroyInstance(instance_, nullptr);
    instance_ = VK_NULL_HANDLE;
  }
}

uint32_t Context::memory_type(uint32_t type_bits, VkMemoryPropertyFlags required,
                              VkMemoryPropertyFlags preferred) const {
  for (VkMemoryPropertyFlags wanted : {required | preferred, required})
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
      if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  throw Error("the Vulkan device has no suitable memory type");
}

double Context::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = command_pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &alloc, &cmd), "vkAllocateCommandBuffers");
  struct Release {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~Release() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
  } release{device_, command_pool_, cmd};

  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  if (has_timestamps_) {
    vkCmdResetQueryPool(cmd, timestamps_, 0, 2);
    vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, timestamps_, 0);
  }
  record(cmd);
  if (has_timestamps_) vkCmdWriteTimestamp(cmd, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, timestamps_, 1);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");

  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  check(vkResetFences(device_, 1, &fence_), "vkResetFences");
  check(vkQueueSubmit(queue_, 1, &submit, fence_), "vkQueueSubmit");
  check(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");

  if (!has_timestamps_) return -1.0;
  uint64_t ticks[2] = {0, 0};
  check(vkGetQueryPoolResults(device_, timestamps_, 0, 2, sizeof(ticks), ticks, sizeof(uint64_t),
                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
        "vkGetQueryPoolResults");
  return static_cast<double>(ticks[1] - ticks[0]) * limits_.timestampPeriod * 1e-6;
}

}  // namespace facet::vk
