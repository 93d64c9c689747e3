#include "vk/pipeline_cache.hpp"

namespace facet::vk {

CompiledKernel::~CompiledKernel() {
  if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
  if (layout) vkDestroyPipelineLayout(device, layout, nullptr);
  if (set_layout) vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
}

std::shared_ptr<const CompiledKernel> PipelineCache::get(
    PipelineKey key, const std::function<std::shared_ptr<const CompiledKernel>()>& compile) {
  {
    std::lock_guard lock(mutex_);
    auto found = entries_.find(key);
    if (found != entries_.end()) return found->second;
  }
  // Compiled unlocked, so another thread's kernels (the texture upload's MIP builder beside the direct
  // pass's compilation) do not wait for it; if two threads compile one key, the first entry stays.
  auto compiled = compile();
  std::lock_guard lock(mutex_);
  return entries_.emplace(std::move(key), std::move(compiled)).first->second;
}

std::size_t PipelineCache::size() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

void PipelineCache::clear() {
  std::lock_guard lock(mutex_);
  entries_.clear();
}

}  // namespace facet::vk
