// Frame time of the colour-mapped texture methods on scenes/colormap_noise_plane.json and
// scenes/colormap_objects.json at 1280x720 (GPU timestamps of the direct pass, manual time; pipeline
// JIT and the scene upload excluded by a warm-up frame), with each method's RMSE against a 16x16
// jittered CPU reference at 320x180 as a counter (the reference is cached in the build tree), so
// speed and error of every variant are read side by side.
#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <map>
#include <string>

#include "cpu/reference_renderer.hpp"
#include "gpu/direct_pass.hpp"
#include "image/exr_io.hpp"
#include "image/metrics.hpp"
#include "scene/scene_loader.hpp"
#include "vk/context.hpp"

namespace {

facet::vk::Context& context() {
  static facet::vk::Context instance{facet::vk::ContextOptions{}};
  return instance;
}

const facet::Scene& scene(const std::string& name) {
  static std::map<std::string, facet::Scene> scenes;
  auto it = scenes.find(name);
  if (it == scenes.end())
    it = scenes.emplace(name, facet::load_scene(std::string(FACET_SOURCE_DIR) + "/scenes/" + name + ".json")).first;
  return it->second;
}

constexpr int kErrorWidth = 320, kErrorHeight = 180;

// Rendered once and cached in the build tree (it takes tens of seconds on the CPU).
const facet::Image& reference(const std::string& name) {
  static std::map<std::string, facet::Image> images;
  auto it = images.find(name);
  if (it != images.end()) return it->second;
  const facet::Image image = [&] {
    const std::filesystem::path cache = std::string(FACET_BINARY_DIR) + "/" + name + "_reference_320x180_16.exr";
    if (std::filesystem::exists(cache)) return facet::read_exr(cache);
    facet::cpu::ReferenceOptions options;
    options.width = kErrorWidth;
    options.height = kErrorHeight;
    options.grid = 16;
    options.seed = 7;
    facet::Image rendered = facet::cpu::render_reference(scene(name), options);
    facet::write_exr(cache, rendered, {}, facet::ExrPixelType::Float);
    return rendered;
  }();
  return images.emplace(name, image).first->second;
}

// CPU time of the whole process (lavapipe's worker threads run in it): the work a frame costs, far
// less disturbed than its wall or GPU-timestamp time when other processes load the machine.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

void BM_Scene(benchmark::State& state, const std::string& name, const std::string& method_name) {
  const facet::gpu::RenderMethod method = facet::gpu::RenderMethod::parse(method_name);
  facet::gpu::DirectPass pass(context(), scene(name), method);
  const facet::Camera& camera = scene(name).camera;
  pass.render(camera, 1280, 720);  // JIT warm-up
  double cpu_ms = 0.0;
  for (auto _ : state) {
    facet::gpu::RenderStats stats;
    const double cpu_start = process_cpu_ms();
    pass.render(camera, 1280, 720, &stats);
    cpu_ms += process_cpu_ms() - cpu_start;
    state.SetIterationTime(stats.gpu_ms * 1e-3);
  }
  state.counters["process_cpu_ms"] = cpu_ms / static_cast<double>(state.iterations());
  state.counters["rmse_320x180"] = facet::rmse(pass.render(camera, kErrorWidth, kErrorHeight), reference(name));
}

#define FACET_TEXTURE_BENCH(scene_name, tag, method, iterations)                                 \
  BENCHMARK_CAPTURE(BM_Scene, scene_name##_##tag, std::string(#scene_name), std::string(method)) \
      ->UseManualTime()                                                                          \
      ->Unit(benchmark::kMillisecond)                                                            \
      ->Iterations(iterations)

FACET_TEXTURE_BENCH(colormap_noise_plane, naive, "naive", 5);
FACET_TEXTURE_BENCH(colormap_noise_plane, mip, "mip", 5);
FACET_TEXTURE_BENCH(colormap_noise_plane, colormip, "colormip", 5);
FACET_TEXTURE_BENCH(colormap_noise_plane, filtered, "filtered", 5);
FACET_TEXTURE_BENCH(colormap_noise_plane, filtered_table, "filtered:table", 5);
FACET_TEXTURE_BENCH(colormap_noise_plane, ss8, "ss:8", 1);
FACET_TEXTURE_BENCH(colormap_objects, naive, "naive", 5);
FACET_TEXTURE_BENCH(colormap_objects, colormip, "colormip", 5);
FACET_TEXTURE_BENCH(colormap_objects, filtered, "filtered", 5);
FACET_TEXTURE_BENCH(colormap_objects, filtered_table, "filtered:table", 3);
FACET_TEXTURE_BENCH(colormap_objects, ss8, "ss:8", 1);

}  // namespace
