// Runs shaders/render/diffraction_orders.glsl on the GPU through the test probe
// (bench/probes/orders_probe.comp, run by direction_pair_probe.hpp): used by the GPU test and the benchmark.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "diffraction/order_wavelengths.hpp"
#include "direction_pair_probe.hpp"
#include "gpu/diffraction_layout.hpp"
#include "orders_probe.spv.h"

namespace facet::test {

struct OrdersProbePush {
  glm::vec4 lattice0;
  glm::vec4 lattice1;
  glm::ivec4 repeats;
  glm::vec4 pixel;
  float pixel_reach;
  float pad[3];
  glm::ivec4 shape;
  glm::vec4 scales;
  float lambda0_nm;
  int entries;
  uint32_t count;
};

// pixel_steps: the mean over a pixel whose (u, v) moves by them per pixel step (evaluate_orders' argument).
inline ProbeRun run_orders_probe(vk::Context& context, const diffraction::SpectralTables& tables,
                                 const diffraction::OrderWavelengths& plan,
                                 const std::vector<std::pair<glm::dvec3, glm::dvec3>>& pairs,
                                 std::optional<glm::dvec4> pixel_steps = std::nullopt) {
  std::vector<glm::vec4> observer;
  for (const glm::dvec3& o : plan.observer) observer.emplace_back(glm::vec3(o), 0.0f);
  const std::vector<glm::vec2> coefficients = tables.coefficients_f32();
  auto table = vk::Buffer::from(context, std::span<const glm::vec2>(coefficients));
  auto observer_buffer = vk::Buffer::from(context, std::span<const glm::vec4>(observer));
  const auto& L = plan.lattice;
  const gpu::DiffractionTableInfo info = gpu::table_info(tables);
  const OrdersProbePush push{glm::vec4(glm::vec2(L.frequency), L.sigma_nm, L.reach),
                             glm::vec4(L.k_min, L.k_max, L.peak_step, L.max_step),
                             glm::ivec4(L.repeats, L.pixel_budget, pixel_steps ? 1 : 0),
                             glm::vec4(pixel_steps.value_or(glm::dvec4(0.0))),
                             float(L.pixel_reach),
                             {},
                             info.shape,
                             info.scales,
                             float(plan.lambda0_nm),
                             static_cast<int>(plan.observer.size()),
                             static_cast<uint32_t>(pairs.size())};
  const std::array<const vk::Buffer*, 2> tables_bound = {&table, &observer_buffer};
  return run_direction_pair_probe(context, "orders_probe", orders_probe_spv, pairs, tables_bound, push);
}

}  // namespace facet::test
