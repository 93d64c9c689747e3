// Frame time of the microsurface methods on the microsurface scenes at 1280x720 (GPU
// timestamps of the direct pass, manual time; pipeline JIT and upload excluded by a warm-up frame),
// with each method's RMSE against a 16x16 jittered CPU reference at 320x180 as a counter (the
// reference traces the height field; cached in the build tree).
#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <string>

#include "cpu/reference_renderer.hpp"
#include "gpu/direct_pass.hpp"
#include "image/exr_io.hpp"
#include "image/metrics.hpp"
#include "scene/scene_loader.hpp"
#include "vk/context.hpp"

namespace {

constexpr int kErrorWidth = 320, kErrorHeight = 180, kErrorGrid = 16;

facet::vk::Context& context() {
  static facet::vk::Context instance{facet::vk::ContextOptions{}};
  return instance;
}

facet::Scene load(const std::string& name) {
  return facet::load_scene(std::string(FACET_SOURCE_DIR) + "/scenes/" + name + ".json");
}

facet::Image reference(const std::string& name, const facet::Scene& scene) {
  const std::filesystem::path cache = std::string(FACET_BINARY_DIR) + "/" + name + "_reference_320x180_16.exr";
  if (std::filesystem::exists(cache)) return facet::read_exr(cache);
  facet::cpu::ReferenceOptions options;
  options.width = kErrorWidth;
  options.height = kErrorHeight;
  options.grid = kErrorGrid;
  options.seed = 7;
  facet::Image rendered = facet::cpu::render_reference(scene, options);
  facet::write_exr(cache, rendered, {}, facet::ExrPixelType::Float);
  return rendered;
}

// CPU time of the whole process (lavapipe's worker threads run in it): the work a frame costs, far
// less disturbed by other processes than GPU-timestamp time; on 2 idle cores a frame takes about half.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

void BM_Microsurface(benchmark::State& state, const std::string& scene_name, const std::string& method_name) {
  const facet::Scene scene = load(scene_name);
  facet::gpu::DirectPass pass(context(), scene, facet::gpu::RenderMethod::parse(method_name));
  pass.render(scene.camera, 64, 36);  // JIT warm-up (the first dispatch of a pipeline compiles it)
  double cpu_ms = 0.0;
  for (auto _ : state) {
    facet::gpu::RenderStats stats;
    const double cpu_start = process_cpu_ms();
    pass.render(scene.camera, 1280, 720, &stats);
    cpu_ms += process_cpu_ms() - cpu_start;
    state.SetIterationTime(stats.gpu_ms * 1e-3);
  }
  state.counters["process_cpu_ms"] = cpu_ms / static_cast<double>(state.iterations());
  state.counters["rmse_320x180"] =
      facet::rmse(pass.render(scene.camera, kErrorWidth, kErrorHeight), reference(scene_name, scene));
}

#define FACET_MICROSURFACE_BENCH(scene, method, label, iterations)                              \
  BENCHMARK_CAPTURE(BM_Microsurface, scene##_##label, std::string(#scene), std::string(method)) \
      ->UseManualTime()                                                                         \
      ->Unit(benchmark::kMillisecond)                                                           \
      ->Iterations(iterations)
#define FACET_MICROSURFACE_SCENE(scene)                     \
  FACET_MICROSURFACE_BENCH(scene, "naive", naive, 3);       \
  FACET_MICROSURFACE_BENCH(scene, "mip", mip, 3);           \
  FACET_MICROSURFACE_BENCH(scene, "colormip", colormip, 3); \
  FACET_MICROSURFACE_BENCH(scene, "filtered", filtered, 3); \
  FACET_MICROSURFACE_BENCH(scene, "ss:8", ss8, 1)

FACET_MICROSURFACE_SCENE(microsurface_terrain);
FACET_MICROSURFACE_SCENE(microsurface_slope);
FACET_MICROSURFACE_SCENE(microsurface_glossy);
FACET_MICROSURFACE_SCENE(microsurface_rough_diagonal);
FACET_MICROSURFACE_SCENE(microsurface_horizon);
FACET_MICROSURFACE_SCENE(microsurface_steep);
FACET_MICROSURFACE_SCENE(microsurface_fine_ground);

}  // namespace
