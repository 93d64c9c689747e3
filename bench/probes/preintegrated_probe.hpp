// Runs shaders/render/diffraction_preintegrated.glsl on the GPU through the test probe
// (bench/probes/preintegrated_probe.comp): used by the GPU test and the benchmark.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/preintegrated_tables.hpp"
#include "preintegrated_probe.spv.h"
#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/kernel.hpp"

namespace facet::test {

struct PreintegratedProbePush {
  glm::vec4 grid;
  glm::ivec4 shape;
  glm::vec4 scalars;
  float R0;
  uint32_t count;
};

struct PreintegratedProbeRun {
  std::vector<glm::dvec3> rgb;
  double gpu_ms;
};

inline PreintegratedProbeRun run_preintegrated_probe(vk::Context& context, const diffraction::PreintegratedTables& t,
                                                     const std::vector<std::pair<glm::dvec3, glm::dvec3>>& pairs) {
  std::vector<glm::vec4> queries;
  for (const auto& [wi, wr] : pairs) {
    queries.emplace_back(glm::vec3(wi), 0.0f);
    queries.emplace_back(glm::vec3(wr), 0.0f);
  }
  auto in = vk::Buffer::from(context, std::span<const glm::vec4>(queries));
  vk::Buffer out(context, pairs.size() * sizeof(glm::vec4));
  auto words = vk::Buffer::from(context, std::span<const uint32_t>(t.packed));
  auto scales = vk::Buffer::from(context, std::span<const float>(t.scale));
  vk::Kernel kernel(context, {.name = "preintegrated_probe",
                              .spirv = preintegrated_probe_spv,
                              .buffer_count = 4,
                              .push_constant_bytes = sizeof(PreintegratedProbePush),
                              .specialization = {}});
  const PreintegratedProbePush push{glm::vec4(glm::vec2(t.origin), glm::vec2(t.spacing)),
                                    glm::ivec4(t.nu, t.nv, t.terms, t.words),
                                    glm::vec4(t.w_centre, t.floor_lambda_nm, t.sigma_nm, t.hs_nm), float(t.R0),
                                    static_cast<uint32_t>(pairs.size())};
  const std::array<const vk::Buffer*, 4> bindings = {&in, &out, &words, &scales};
  PreintegratedProbeRun run;
  run.gpu_ms = kernel.dispatch(bindings, &push, {static_cast<uint32_t>((pairs.size() + 63) / 64), 1, 1});
  std::vector<glm::vec4> raw(pairs.size());
  out.download(raw.data(), raw.size() * sizeof(glm::vec4));
  for (const auto& r : raw) run.rgb.emplace_back(glm::vec3(r));
  return run;
}

}  // namespace facet::test
