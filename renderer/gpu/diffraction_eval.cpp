#include "gpu/diffraction_eval.hpp"

#include <array>

#include "common/error.hpp"
#include "common/format_mib.hpp"
#include "eval_diffraction.spv.h"
#include "gpu/diffraction_layout.hpp"
#include "vk/buffer.hpp"

namespace facet::gpu {

std::vector<diffraction::DiffractionResult> evaluate_diffraction(vk::Context& context,
                                                                 const diffraction::SpectralTables& tables,
                                                                 std::span<const diffraction::DiffractionQuery> queries,
                                                                 BatchTiming* timing) {
  std::vector<diffraction::DiffractionResult> results;
  if (queries.empty()) return results;
  std::vector<EvalRecord> records;
  records.reserve(queries.size());
  for (const auto& q : queries)
    records.push_back({glm::vec4(glm::vec3(q.wi), q.lambda_nm), glm::vec4(glm::vec3(q.wr), 0.0f)});
  const std::vector<glm::vec2> coefficients = tables.coefficients_f32();
  if (coefficients.size() * sizeof(glm::vec2) > context.limits().maxStorageBufferRange)
    throw Error("diffraction tables of " + format_mib(coefficients.size() * sizeof(glm::vec2)) +
                " exceed the device's storage-buffer range of " + format_mib(context.limits().maxStorageBufferRange) +
                ", the limit of --device gpu (it reads them as one storage buffer; --device cpu has none): use fewer "
                "samples or a larger tolerance");

  const std::array<DiffractionTableInfo, 1> info = {table_info(tables)};
  auto table = vk::Buffer::from(context, std::span<const glm::vec2>(coefficients));
  auto info_buffer = vk::Buffer::from(context, std::span<const DiffractionTableInfo>(info));
  // Bound after the shared in/out slots, at eval_diffraction's named slots (layout/eval_layout.glsl).
  std::array<const vk::Buffer*, FACET_EVAL_DIFFRACTION_BINDING_COUNT - FACET_EVAL_BINDING_COUNT> table_bindings{};
  table_bindings[FACET_EVAL_BINDING_DIFFRACTION_TABLE - FACET_EVAL_BINDING_COUNT] = &table;
  table_bindings[FACET_EVAL_BINDING_DIFFRACTION_INFO - FACET_EVAL_BINDING_COUNT] = &info_buffer;
  const std::vector<EvalRecord> raw =
      run_batch_eval(context, "eval_diffraction", eval_diffraction_spv, records, timing, table_bindings);
  for (const auto& r : raw) results.push_back({r.a.x, r.a.y});
  return results;
}

}  // namespace facet::gpu
