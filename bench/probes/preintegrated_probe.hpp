// Runs shaders/render/diffraction_preintegrated.glsl on the GPU through the test probe
// (bench/probes/preintegrated_probe.comp, run by direction_pair_probe.hpp): used by the GPU test and the benchmark.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/preintegrated_tables.hpp"
#include "direction_pair_probe.hpp"
#include "preintegrated_probe.spv.h"

namespace facet::test {

struct PreintegratedProbePush {
  glm::vec4 grid;
  glm::ivec4 shape;
  glm::vec4 scalars;
  float R0;
  uint32_t count;
};

inline ProbeRun run_preintegrated_probe(vk::Context& context, const diffraction::PreintegratedTables& t,
                                        const std::vector<std::pair<glm::dvec3, glm::dvec3>>& pairs) {
  auto words = vk::Buffer::from(context, std::span<const uint32_t>(t.packed));
  auto scales = vk::Buffer::from(context, std::span<const float>(t.scale));
  const PreintegratedProbePush push{
      glm::vec4(glm::vec2(t.origin), glm::vec2(t.spacing)), glm::ivec4(t.nu, t.nv, t.terms, t.words),
      glm::vec4(t.w_centre, t.floor_lambda_nm, t.sigma_nm, t.hs_nm), float(t.R0), static_cast<uint32_t>(pairs.size())};
  const std::array<const vk::Buffer*, 2> tables = {&words, &scales};
  return run_direction_pair_probe(context, "preintegrated_probe", preintegrated_probe_spv, pairs, tables, push);
}

}  // namespace facet::test
