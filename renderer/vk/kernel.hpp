// A compute kernel: a SPIR-V module specialised into a pipeline, with buffers at bindings 0..B-1
// of set 0 (each a storage buffer, a uniform buffer or a uniform texel buffer), storage images at
// bindings B..B+I-1, and an optional push-constant block.
//
// Specialization constants select features at pipeline creation, so a scene compiles only
// what it uses; kernels with the same module and specialization share one compiled pipeline
// (vk/pipeline_cache.hpp). Each dispatch() is its own submission, so callers split long work into
// tiles and no single submission runs for seconds.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>
#include <glm/glm.hpp>

#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/pipeline_cache.hpp"
#include "vk/storage_image.hpp"

namespace facet::vk {

struct SpecConstant {
  uint32_t id;
  uint32_t value;  // 32-bit: int, uint, bool (0/1) or a float's bits
};

struct KernelDesc {
  std::string name;  // for error messages
  std::span<const uint32_t> spirv;
  uint32_t buffer_count = 0;
  uint32_t push_constant_bytes = 0;
  uint32_t image_count = 0;
  std::vector<SpecConstant> specialization;
  std::vector<BufferKind> buffer_kinds = {};  // per binding; bindings beyond it are Storage
};

class Kernel {
 public:
  Kernel(Context& context, const KernelDesc& desc);
  Kernel(const Kernel&) = delete;
  Kernel& operator=(const Kernel&) = delete;

  // Binds buffers[i] at binding i, pushes `push` (push_constant_bytes of it), dispatches
  // `groups` workgroups and waits. Returns the GPU time in milliseconds.
  double dispatch(std::span<const Buffer* const> buffers, const void* push, glm::uvec3 groups);
  // The same with storage images at bindings buffer_count.. (a kernel with image_count > 0).
  double dispatch(std::span<const Buffer* const> buffers, std::span<const StorageImage* const> images, const void* push,
                  glm::uvec3 groups);

 private:
  Context* context_;
  std::string name_;
  uint32_t buffer_count_;
  std::vector<BufferKind> buffer_kinds_;  // one per binding
  uint32_t image_count_;
  uint32_t push_constant_bytes_;
  static std::shared_ptr<const CompiledKernel> compile(VkDevice device, const KernelDesc& desc,
                                                       std::span<const BufferKind> kinds);

  std::shared_ptr<const CompiledKernel> compiled_;
};

}  // namespace facet::vk
