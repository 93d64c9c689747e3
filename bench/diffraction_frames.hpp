// Whole frames of the diffraction scenes, shared by diffraction_bench (BM_RenderFrame) and
// diffraction_fast_bench (BM_RenderScene): 512 x 512 on the GPU (manual time = the render pass's
// GPU timestamps) and the error of the same method at 128 x 128 against the same pixel-centre rays
// shaded in double with the exact transform (Chebyshev-interpolated exact bins, error < 1e-12) at
// 0.25 nm wavelength spacing, so only the GPU's Taylor truncation, wavelength sampling and float
// rounding remain. Scene index: 0 plate, 1 snake.
#pragma once

#include <map>

#include <benchmark/benchmark.h>

#include "cpu/direct_cpu.hpp"
#include "gpu/direct_pass.hpp"
#include "image/flip.hpp"
#include "image/metrics.hpp"
#include "scene/scene_loader.hpp"
#include "vk/context.hpp"

namespace facet::bench {

inline const Scene& diffraction_scene(int index) {
  static const Scene scenes[] = {load_scene(FACET_SOURCE_DIR "/scenes/diffraction_plate.json"),
                                 load_scene(FACET_SOURCE_DIR "/scenes/snake_fingers.json")};
  return scenes[index];
}

inline constexpr int kErrorSide = 128;

inline const Image& exact_diffraction_frame(int index) {
  static std::map<int, Image> cache;
  auto it = cache.find(index);
  if (it == cache.end()) {
    diffraction::DiffractionSettings fine;
    fine.wavelengths = 1881;
    it = cache
             .emplace(index, cpu::render_direct_cpu(diffraction_scene(index), kErrorSide, kErrorSide, fine,
                                                    cpu::DiffractionShading::Transform::Exact))
             .first;
  }
  return it->second;
}

// Times 512 x 512 frames of scene `index` rendered by `method` and sets the rmse, max_abs and flip
// counters of its 128 x 128 frame against the exact one.
inline void measure_diffraction_frame(benchmark::State& state, int index, const gpu::RenderMethod& method) {
  static vk::Context context{vk::ContextOptions{}};
  const Scene& scene = diffraction_scene(index);
  gpu::DirectPass pass(context, scene, method);
  pass.render(scene.camera, 64, 64);  // JIT warm-up
  for (auto _ : state) {
    gpu::RenderStats stats;
    benchmark::DoNotOptimize(pass.render(scene.camera, 512, 512, &stats));
    state.SetIterationTime(stats.gpu_ms * 1e-3);
  }
  const Image test = pass.render(scene.camera, kErrorSide, kErrorSide);
  const Image& exact = exact_diffraction_frame(index);
  state.counters["rmse"] = rmse(test, exact);
  state.counters["max_abs"] = max_abs_error(test, exact);
  state.counters["flip"] = flip(test, exact);
}

}  // namespace facet::bench
