#include "diffraction/diffraction_gpu.hpp"

#include <algorithm>
#include <array>

#include "common/error.hpp"
#include "eval_diffraction.spv.h"
#include "vk/buffer.hpp"
#include "vk/kernel.hpp"

namespace facet::diffraction {

std::vector<DiffractionResult> evaluate_gpu(vk::Context& context, const SpectralTables& tables,
                                            std::span<const DiffractionQuery> queries, gpu::BatchTiming* timing) {
  std::vector<DiffractionResult> results;
  if (queries.empty()) return results;
  std::vector<gpu::EvalRecord> records;
  records.reserve(queries.size());
  for (const auto& q : queries)
    records.push_back({glm::vec4(glm::vec3(q.wi), q.lambda_nm), glm::vec4(glm::vec3(q.wr), 0.0f)});
  const std::vector<glm::vec2> coefficients = tables.coefficients_f32();
  const uint64_t limit = context.limits().maxStorageBufferRange;
  if (coefficients.size() * sizeof(glm::vec2) > limit)
    throw Error("diffraction tables of " + std::to_string(coefficients.size() * sizeof(glm::vec2) >> 20) +
                " MiB exceed the device's storage buffer range; use fewer samples or a larger tolerance");
  if (records.size() * sizeof(gpu::EvalRecord) > limit)
    throw Error("eval_diffraction: too many records for one storage buffer; split the input");

  const std::array<DiffractionTableInfo, 1> info = {tables.info()};
  auto in = vk::Buffer::from(context, std::span<const gpu::EvalRecord>(records));
  vk::Buffer out(context, records.size() * sizeof(gpu::EvalRecord));
  auto table = vk::Buffer::from(context, std::span<const glm::vec2>(coefficients));
  auto info_buffer = vk::Buffer::from(context, std::span<const DiffractionTableInfo>(info));
  vk::Kernel kernel(context, {.name = "eval_diffraction",
                              .spirv = eval_diffraction_spv,
                              .buffer_count = 4,
                              .push_constant_bytes = sizeof(gpu::EvalRange),
                              .specialization = {}});
  const std::array<const vk::Buffer*, 4> bindings = {&in, &out, &table, &info_buffer};
  const uint64_t per_dispatch =
      static_cast<uint64_t>(context.limits().maxComputeWorkGroupCount[0]) * FACET_EVAL_WORKGROUP;
  gpu::BatchTiming local;
  for (uint64_t offset = 0; offset < records.size(); offset += per_dispatch) {
    const uint64_t count = std::min<uint64_t>(per_dispatch, records.size() - offset);
    gpu::EvalRange range{glm::uvec4(offset, records.size(), 0, 0)};
    local.gpu_ms += kernel.dispatch(
        bindings, &range, {static_cast<uint32_t>((count + FACET_EVAL_WORKGROUP - 1) / FACET_EVAL_WORKGROUP), 1, 1});
    ++local.dispatches;
  }
  std::vector<gpu::EvalRecord> raw(records.size());
  out.download(raw.data(), raw.size() * sizeof(gpu::EvalRecord));
  for (const auto& r : raw) results.push_back({r.a.x, r.a.y});
  if (timing) *timing = local;
  return results;
}

}  // namespace facet::diffraction
