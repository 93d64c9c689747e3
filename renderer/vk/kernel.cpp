#include "vk/kernel.hpp"

#include <utility>

#include "common/error.hpp"

namespace facet::vk {

namespace {
VkDescriptorType descriptor_type(BufferKind kind) {
  switch (kind) {
    case BufferKind::Uniform: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case BufferKind::Texels: return VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    case BufferKind::StorageTexels: return VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER;
    case BufferKind::Storage: break;
  }
  return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

// The most bytes a binding of `kind` may hold (texel buffers: in elements of `texel_bytes`), and its
// name for the error.
std::pair<VkDeviceSize, const char*> binding_range(BufferKind kind, VkDeviceSize texel_bytes,
                                                   const VkPhysicalDeviceLimits& limits) {
  switch (kind) {
    case BufferKind::Uniform: return {limits.maxUniformBufferRange, "uniform buffer range"};
    case BufferKind::Texels:
    case BufferKind::StorageTexels: return {texel_bytes * limits.maxTexelBufferElements, "texel buffer size"};
    case BufferKind::Storage: break;
  }
  return {limits.maxStorageBufferRange, "storage buffer range"};
}

std::vector<BufferKind> kinds_of(const KernelDesc& desc) {
  if (desc.buffer_kinds.size() > desc.buffer_count)
    throw Error("internal: kernel " + desc.name + ": more buffer kinds than buffers");
  std::vector<BufferKind> kinds = desc.buffer_kinds;
  kinds.resize(desc.buffer_count, BufferKind::Storage);
  return kinds;
}
}  // namespace

Kernel::Kernel(Context& context, const KernelDesc& desc)
    : context_(&context),
      name_(desc.name),
      buffer_count_(desc.buffer_count),
      buffer_kinds_(kinds_of(desc)),
      image_count_(desc.image_count),
      push_constant_bytes_(desc.push_constant_bytes) {
  if (desc.push_constant_bytes > context.limits().maxPushConstantsSize)
    throw Error("kernel " + name_ + ": push constants exceed the device limit");
  PipelineKey key{
      {desc.spirv.begin(), desc.spirv.end()}, desc.buffer_count, desc.image_count, desc.push_constant_bytes, {}, {}};
  for (BufferKind kind : buffer_kinds_) key.buffer_kinds.push_back(static_cast<uint32_t>(kind));
  for (const auto& constant : desc.specialization) key.specialization.emplace_back(constant.id, constant.value);
  compiled_ = context.pipelines().get(std::move(key), [&] { return compile(context.device(), desc, buffer_kinds_); });
}

std::shared_ptr<const CompiledKernel> Kernel::compile(VkDevice device, const KernelDesc& desc,
                                                      std::span<const BufferKind> kinds) {
  auto compiled = std::make_shared<CompiledKernel>();
  compiled->device = device;
  std::vector<VkDescriptorSetLayoutBinding> bindings(desc.buffer_count + desc.image_count);
  for (uint32_t i = 0; i < bindings.size(); ++i)
    bindings[i] = {i, i < desc.buffer_count ? descriptor_type(kinds[i]) : VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1,
                   VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  set_info.bindingCount = static_cast<uint32_t>(bindings.size());
  set_info.pBindings = bindings.data();
  check(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &compiled->set_layout), "vkCreateDescriptorSetLayout");

  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, desc.push_constant_bytes};
  VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layout_info.setLayoutCount = 1;
  layout_info.pSetLayouts = &compiled->set_layout;
  layout_info.pushConstantRangeCount = desc.push_constant_bytes > 0 ? 1 : 0;
  layout_info.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(device, &layout_info, nullptr, &compiled->layout), "vkCreatePipelineLayout");

  VkShaderModuleCreateInfo module_info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  module_info.codeSize = desc.spirv.size_bytes();
  module_info.pCode = desc.spirv.data();
  VkShaderModule module = VK_NULL_HANDLE;
  check(vkCreateShaderModule(device, &module_info, nullptr, &module), "vkCreateShaderModule");

  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> values;
  for (const auto& constant : desc.specialization) {
    entries.push_back({constant.id, static_cast<uint32_t>(values.size() * sizeof(uint32_t)), sizeof(uint32_t)});
    values.push_back(constant.value);
  }
  VkSpecializationInfo specialization{static_cast<uint32_t>(entries.size()), entries.data(),
                                      values.size() * sizeof(uint32_t), values.data()};
  VkComputePipelineCreateInfo pipeline_info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  pipeline_info.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
  pipeline_info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  pipeline_info.stage.module = module;
  pipeline_info.stage.pName = "main";
  pipeline_info.stage.pSpecializationInfo = entries.empty() ? nullptr : &specialization;
  pipeline_info.layout = compiled->layout;
  VkResult result = vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipeline_info, nullptr, &compiled->pipeline);
  vkDestroyShaderModule(device, module, nullptr);
  check(result, ("vkCreateComputePipelines (" + desc.name + ")").c_str());
  return compiled;
}

double Kernel::dispatch(std::span<const Buffer* const> buffers, const void* push, glm::uvec3 groups) {
  return dispatch(buffers, {}, push, groups);
}

double Kernel::dispatch(std::span<const Buffer* const> buffers, std::span<const StorageImage* const> images,
                        const void* push, glm::uvec3 groups) {
  if (buffers.size() != buffer_count_ || images.size() != image_count_)
    throw Error("internal: kernel " + name_ + " expects " + std::to_string(buffer_count_) + " buffers and " +
                std::to_string(image_count_) + " images");
  const auto& limits = context_->limits();
  for (int axis = 0; axis < 3; ++axis)
    if (groups[axis] > limits.maxComputeWorkGroupCount[axis])
      throw Error("kernel " + name_ + ": dispatch of " + std::to_string(groups[axis]) +
                  " workgroups exceeds the device limit");
  for (size_t i = 0; i < buffers.size(); ++i)
    if (!buffers[i]) throw Error("internal: kernel " + name_ + ": no buffer at binding " + std::to_string(i));
  for (size_t i = 0; i < buffers.size(); ++i) {
    const auto [range, what] = binding_range(buffer_kinds_[i], buffers[i]->texel_bytes(), limits);
    if (buffers[i]->size() > range)
      throw Error("kernel " + name_ + ": a buffer of " + std::to_string(buffers[i]->size()) +
                  " bytes exceeds the device's " + what + " of " + std::to_string(range) + " bytes");
  }

  VkDevice device = context_->device();
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = context_->descriptor_pool();
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &compiled_->set_layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  check(vkAllocateDescriptorSets(device, &alloc, &set), "vkAllocateDescriptorSets");
  struct Release {
    VkDevice device;
    VkDescriptorPool pool;
    VkDescriptorSet set;
    ~Release() { vkFreeDescriptorSets(device, pool, 1, &set); }
  } release{device, context_->descriptor_pool(), set};

  std::vector<VkDescriptorBufferInfo> buffer_infos(buffers.size());
  std::vector<VkBufferView> texel_views(buffers.size());
  std::vector<VkDescriptorImageInfo> image_infos(images.size());
  std::vector<VkWriteDescriptorSet> writes(buffers.size() + images.size());
  for (uint32_t i = 0; i < writes.size(); ++i) {
    writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    writes[i].dstSet = set;
    writes[i].dstBinding = i;
    writes[i].descriptorCount = 1;
    if (i < buffers.size() &&
        (buffer_kinds_[i] == BufferKind::Texels || buffer_kinds_[i] == BufferKind::StorageTexels)) {
      texel_views[i] = buffers[i]->texel_view();
      writes[i].descriptorType = descriptor_type(buffer_kinds_[i]);
      writes[i].pTexelBufferView = &texel_views[i];
    } else if (i < buffers.size()) {
      buffer_infos[i] = {buffers[i]->handle(), 0, VK_WHOLE_SIZE};
      writes[i].descriptorType = descriptor_type(buffer_kinds_[i]);
      writes[i].pBufferInfo = &buffer_infos[i];
    } else {
      image_infos[i - buffers.size()] = {VK_NULL_HANDLE, images[i - buffers.size()]->view(), VK_IMAGE_LAYOUT_GENERAL};
      writes[i].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
      writes[i].pImageInfo = &image_infos[i - buffers.size()];
    }
  }
  vkUpdateDescriptorSets(device, static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);

  return context_->submit_and_wait([&](VkCommandBuffer cmd) {
    // Earlier host writes and transfers (uploads) become visible to the shader.
    VkMemoryBarrier before{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    before.srcAccessMask = VK_ACCESS_HOST_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;
    before.dstAccessMask = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 1, &before, 0, nullptr, 0, nullptr);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compiled_->pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compiled_->layout, 0, 1, &set, 0, nullptr);
    if (push_constant_bytes_ > 0)
      vkCmdPushConstants(cmd, compiled_->layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, push_constant_bytes_, push);
    vkCmdDispatch(cmd, groups.x, groups.y, groups.z);
    // Make the shader's writes visible to host reads and to later transfers.
    VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_HOST_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &barrier, 0, nullptr, 0,
                         nullptr);
  });
}

}  // namespace facet::vk
