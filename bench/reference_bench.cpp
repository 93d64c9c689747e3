// Reference renderer throughput: primary samples per second on all cores, per shipped scene
// (targets: >= 10 M/s for colour-mapped textures, >= 1 M/s for traced microsurfaces).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <string>

#include "cpu/reference_renderer.hpp"
#include "scene/scene_loader.hpp"

namespace {

void BM_Reference(benchmark::State& state, const std::string& scene_file) {
  const facet::Scene scene = facet::load_scene(std::filesystem::path(FACET_SOURCE_DIR) / "scenes" / scene_file);
  facet::cpu::ReferenceOptions options;
  options.width = 160;
  options.height = 90;
  options.grid = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(facet::cpu::render_reference(scene, options));
  const double samples = static_cast<double>(options.width) * options.height * options.grid * options.grid;
  state.counters["samples/s"] =
      benchmark::Counter(samples * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(BM_Reference, colormap_noise_plane, "colormap_noise_plane.json")
    ->Arg(8)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Reference, microsurface_terrain, "microsurface_terrain.json")
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Reference, microsurface_slope, "microsurface_slope.json")
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Reference, microsurface_glossy, "microsurface_glossy.json")
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(BM_Reference, default_scene, "default.json")->Arg(4)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
