// Runs a probe shader (bench/probes/*.comp) over pairs of directions (w_i, w_r): binding 0 holds
// them as vec4 pairs, binding 1 receives one RGB per pair, bindings 2.. are the probe's tables;
// 64 invocations per workgroup, push constants ending in the pair count. Shared by the GPU tests
// and the benchmarks of the diffraction fast paths.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "vk/buffer.hpp"
#include "vk/context.hpp"
#include "vk/kernel.hpp"

namespace facet::test {

struct ProbeRun {
  std::vector<glm::dvec3> rgb;
  double gpu_ms;
};

template <class Push>
ProbeRun run_direction_pair_probe(vk::Context& context, const char* name, std::span<const uint32_t> spirv,
                                  const std::vector<std::pair<glm::dvec3, glm::dvec3>>& pairs,
                                  std::span<const vk::Buffer* const> tables, const Push& push) {
  std::vector<glm::vec4> queries;
  for (const auto& [wi, wr] : pairs) {
    queries.emplace_back(glm::vec3(wi), 0.0f);
    queries.emplace_back(glm::vec3(wr), 0.0f);
  }
  auto in = vk::Buffer::from(context, std::span<const glm::vec4>(queries));
  vk::Buffer out(context, pairs.size() * sizeof(glm::vec4));
  std::vector<const vk::Buffer*> bindings = {&in, &out};
  bindings.insert(bindings.end(), tables.begin(), tables.end());
  vk::Kernel kernel(context, {.name = name,
                              .spirv = spirv,
                              .buffer_count = static_cast<uint32_t>(bindings.size()),
                              .push_constant_bytes = sizeof(Push),
                              .specialization = {}});
  ProbeRun run;
  run.gpu_ms = kernel.dispatch(bindings, &push, {static_cast<uint32_t>((pairs.size() + 63) / 64), 1, 1});
  std::vector<glm::vec4> raw(pairs.size());
  out.download(raw.data(), raw.size() * sizeof(glm::vec4));
  for (const auto& r : raw) run.rgb.emplace_back(glm::vec3(r));
  return run;
}

}  // namespace facet::test
