// Runs a batched eval kernel (shaders/eval_*.comp) over many records in as few dispatches as
// the device's workgroup-count limit allows.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "vk/buffer.hpp"
#include "vk/context.hpp"

namespace facet::gpu {

using glm::uvec4;
using glm::vec4;
#include "layout/eval_layout.glsl"
static_assert(sizeof(EvalRecord) == 32);
static_assert(sizeof(EvalRange) == 16);

struct BatchTiming {
  double gpu_ms = 0.0;
  int dispatches = 0;
};

// One output record per input record, in order. `tables` are bound after the input and output
// records (bindings 2, 3, ...), for kernels that read more than the records (eval_diffraction).
std::vector<EvalRecord> run_batch_eval(vk::Context& context, const char* name, std::span<const uint32_t> spirv,
                                       std::span<const EvalRecord> inputs, BatchTiming* timing = nullptr,
                                       std::span<const vk::Buffer* const> tables = {});

}  // namespace facet::gpu
