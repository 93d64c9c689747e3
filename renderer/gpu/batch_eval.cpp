#include "gpu/batch_eval.hpp"

#include <algorithm>
#include <array>
#include <vector>

#include "common/error.hpp"
#include "gpu/contiguous_ids.hpp"
#include "vk/buffer.hpp"
#include "vk/kernel.hpp"

namespace facet::gpu {

// The slots of layout/eval_layout.glsl: every kernel's, then eval_diffraction's two more.
static_assert(contiguous_ids(std::array<int, FACET_EVAL_BINDING_COUNT>{FACET_EVAL_BINDING_IN, FACET_EVAL_BINDING_OUT}));
static_assert(contiguous_ids(
    std::array<int, FACET_EVAL_DIFFRACTION_BINDING_COUNT - FACET_EVAL_BINDING_COUNT>{
        FACET_EVAL_BINDING_DIFFRACTION_TABLE, FACET_EVAL_BINDING_DIFFRACTION_INFO},
    FACET_EVAL_BINDING_COUNT));

std::vector<EvalRecord> run_batch_eval(vk::Context& context, const char* name, std::span<const uint32_t> spirv,
                                       std::span<const EvalRecord> inputs, BatchTiming* timing,
                                       std::span<const vk::Buffer* const> tables) {
  std::vector<EvalRecord> outputs(inputs.size());
  if (inputs.empty()) return outputs;
  const uint64_t bytes = inputs.size_bytes();
  if (bytes > context.limits().maxStorageBufferRange)
    throw Error(std::string(name) + ": " + std::to_string(inputs.size()) +
                " records exceed the device's storage buffer range; split the input");
  auto in = vk::Buffer::from(context, inputs);
  vk::Buffer out(context, bytes);
  vk::Kernel kernel(context, {.name = name,
                              .spirv = spirv,
                              .buffer_count = static_cast<uint32_t>(FACET_EVAL_BINDING_COUNT + tables.size()),
                              .push_constant_bytes = sizeof(EvalRange),
                              .specialization = {}});
  // The kernel's own tables follow the shared slots (eval_diffraction's: FACET_EVAL_BINDING_DIFFRACTION_*).
  std::vector<const vk::Buffer*> bindings(FACET_EVAL_BINDING_COUNT + tables.size());
  bindings[FACET_EVAL_BINDING_IN] = &in;
  bindings[FACET_EVAL_BINDING_OUT] = &out;
  std::copy(tables.begin(), tables.end(), bindings.begin() + FACET_EVAL_BINDING_COUNT);
  const uint64_t per_dispatch =
      static_cast<uint64_t>(context.limits().maxComputeWorkGroupCount[0]) * FACET_EVAL_WORKGROUP;
  BatchTiming local;
  for (uint64_t offset = 0; offset < inputs.size(); offset += per_dispatch) {
    uint64_t count = std::min<uint64_t>(per_dispatch, inputs.size() - offset);
    EvalRange range{uvec4(offset, inputs.size(), 0, 0)};
    local.gpu_ms += kernel.dispatch(
        bindings, &range, {static_cast<uint32_t>((count + FACET_EVAL_WORKGROUP - 1) / FACET_EVAL_WORKGROUP), 1, 1});
    ++local.dispatches;
  }
  out.download(outputs.data(), bytes);
  if (timing) *timing = local;
  return outputs;
}

}  // namespace facet::gpu
