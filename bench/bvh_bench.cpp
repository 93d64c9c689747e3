// Build time of the binned-SAH BVH on random triangle soups.
#include <benchmark/benchmark.h>

#include <random>

#include "scene/bvh.hpp"

namespace {

facet::Mesh soup(size_t count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  facet::Mesh m;
  for (size_t t = 0; t < count; ++t) {
    const glm::dvec3 a = 10.0 * glm::dvec3(u(rng), u(rng), u(rng));
    for (int k = 0; k < 3; ++k) {
      m.indices.push_back(static_cast<uint32_t>(m.positions.size()));
      m.positions.push_back(k == 0 ? a : a + 0.3 * glm::dvec3(u(rng), u(rng), u(rng)));
    }
  }
  return m;
}

void BM_BuildBvh(benchmark::State& state) {
  const std::vector<facet::Mesh> meshes{soup(static_cast<size_t>(state.range(0)))};
  for (auto _ : state) {
    facet::Bvh bvh = facet::build_bvh(meshes);
    benchmark::DoNotOptimize(bvh.nodes.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_BuildBvh)->Arg(1000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
