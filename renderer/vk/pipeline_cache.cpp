#include "vk/pipeline_cache.hpp"

namespace facet::vk {

CompiledKernel::~CompiledKernel() {
  if (pipeline) vkDestroyPipeline(device, pipeline, nullptr);
  if (layout) vkDestroyPipelineLayout(device, layout, nullptr);
  if (set_layout) vkDestroyDescriptorSetLayout(device, set_layout, nullptr);
}

std::shared_ptr<const CompiledKernel> PipelineCache::get(
    PipelineKey key, const std::function<std::shared_ptr<const CompiledKernel>()>& compile) {
  auto found = entries_.find(key);
  if (found != entries_.end()) return found->second;
  auto compiled = compile();
  entries_.emplace(std::move(key), compiled);
  return compiled;
}

}  // namespace facet::vk
