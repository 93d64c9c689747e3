// Compiled compute pipelines, shared by every Kernel of one Context built from the same SPIR-V,
// bindings, push-constant size and specialization. lavapipe compiles a pipeline in 1-2.5 s of CPU
// (its NIR passes dominate; a VkPipelineCache keeps none of that work), so a process that renders a
// scene with several methods or sizes (facet bench, the tests) compiles each variant once. Entries
// live as long as the Context.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include <vulkan/vulkan.h>

namespace facet::vk {

// A pipeline with its layouts; destroys them.
struct CompiledKernel {
  VkDevice device = VK_NULL_HANDLE;
  VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  CompiledKernel() = default;
  CompiledKernel(const CompiledKernel&) = delete;
  CompiledKernel& operator=(const CompiledKernel&) = delete;
  ~CompiledKernel();
};

// What makes two pipelines the same: the module's words (compared in full, not by address) and
// everything the pipeline is created with.
struct PipelineKey {
  std::vector<uint32_t> spirv;
  uint32_t buffer_count = 0;
  uint32_t image_count = 0;
  uint32_t push_constant_bytes = 0;
  std::vector<std::pair<uint32_t, uint32_t>> specialization;  // (id, value), in the caller's order
  std::vector<uint32_t> buffer_kinds;  // vk::BufferKind per binding
  auto operator<=>(const PipelineKey&) const = default;
};

class PipelineCache {
 public:
  // The pipeline for `key`, made by `compile` the first time it is asked for (a throw caches nothing).
  std::shared_ptr<const CompiledKernel> get(PipelineKey key,
                                            const std::function<std::shared_ptr<const CompiledKernel>()>& compile);
  std::size_t size() const;
  void clear();

 private:
  mutable std::mutex mutex_;  // get() may run on two threads (gpu::DirectPass compiles beside its upload)
  std::map<PipelineKey, std::shared_ptr<const CompiledKernel>> entries_;
};

}  // namespace facet::vk
