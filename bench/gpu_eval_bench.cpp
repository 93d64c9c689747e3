// Evaluations per second of the batched GPU eval kernels on the Vulkan device (lavapipe here).
// Time is the GPU timestamp time of the dispatches (manual time), not upload or readback.
#include <benchmark/benchmark.h>

#include <random>
#include <span>
#include <vector>

#include "eval_cross_section.spv.h"
#include "eval_visible_slope.spv.h"
#include "gpu/batch_eval.hpp"
#include "vk/context.hpp"

namespace {

using facet::gpu::EvalRecord;

facet::vk::Context& context() {
  static facet::vk::Context instance{facet::vk::ContextOptions{}};
  return instance;
}

// Times one eval kernel over `inputs` by its GPU timestamps, after a JIT warm-up dispatch.
void run_timed(benchmark::State& state, const char* name, std::span<const uint32_t> spirv,
               const std::vector<EvalRecord>& inputs) {
  facet::gpu::run_batch_eval(context(), name, spirv, inputs);
  for (auto _ : state) {
    facet::gpu::BatchTiming timing;
    facet::gpu::run_batch_eval(context(), name, spirv, inputs, &timing);
    state.SetIterationTime(timing.gpu_ms * 1e-3);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(inputs.size()));
}

// Random slope laws and views over the brief's domain (both sides of the horizon).
std::vector<EvalRecord> visible_slope_inputs(size_t count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  std::vector<EvalRecord> records(count);
  for (auto& r : records) {
    float vx = 0.01f + uni(rng), vy = 0.01f + uni(rng);
    r = {glm::vec4(2 * uni(rng) - 1, 2 * uni(rng) - 1, vx, vy),
         glm::vec4(0.5f * std::sqrt(vx * vy) * (2 * uni(rng) - 1), 1.57f * uni(rng), 6.28f * uni(rng), 0)};
  }
  return records;
}

void BM_GpuVisibleSlope(benchmark::State& state) {
  run_timed(state, "eval_visible_slope", eval_visible_slope_spv,
            visible_slope_inputs(static_cast<size_t>(state.range(0))));
}
BENCHMARK(BM_GpuVisibleSlope)->Arg(1 << 22)->UseManualTime()->Unit(benchmark::kMillisecond);

// The fast cross-section of one distribution (range(1) = ndf id) at random (param, u).
void BM_GpuCrossSection(benchmark::State& state) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<float> uni(0.0f, 1.0f);
  const int ndf = static_cast<int>(state.range(1));
  std::vector<EvalRecord> inputs(static_cast<size_t>(state.range(0)));
  for (auto& r : inputs) {
    float param = ndf == 2 ? uni(rng) * 0.999f : std::pow(10.0f, -3.0f + 6.0f * uni(rng));
    r = {glm::vec4(ndf, param, 2 * uni(rng) - 1, 0), glm::vec4(0)};
  }
  run_timed(state, "eval_cross_section", eval_cross_section_spv, inputs);
}
BENCHMARK(BM_GpuCrossSection)
    ->ArgsProduct({{1 << 22}, {0, 1, 2, 3}})
    ->ArgNames({"n", "ndf"})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
