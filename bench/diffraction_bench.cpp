// Diffraction: precomputation of the spectral tables (FFTW, double) and BRDF evaluations per
// second on the CPU (double, one thread) and the GPU (float; manual time = GPU timestamps) as a
// function of the number of Taylor terms N; 512 x 512 frames of the diffraction scenes on the GPU
// against the wavelength count and N, with each setting's error against the exact transform.
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "diffraction/spectral_tables.hpp"
#include "diffraction_frames.hpp"
#include "gpu/diffraction_eval.hpp"
#include "scene/grating/grating.hpp"
#include "vk/context.hpp"

namespace {

using namespace facet::diffraction;

Grating fingers(int samples, double amplitude_nm) {
  return grating_from_json({{"type", "fingers"},
                            {"period_nm", 1000},
                            {"amplitude_nm", amplitude_nm},
                            {"size_um", 64},
                            {"samples", samples},
                            {"finger_length_nm", 4000}},
                           "bench");
}

// Snake-scale-like ridges of 150 nm (k w h up to ~5 at 380 nm): N = 19 terms at tolerance 1e-4.
void BM_Precompute(benchmark::State& state) {
  const Grating g = fingers(static_cast<int>(state.range(0)), 150.0);
  SpectralTables t;
  for (auto _ : state) benchmark::DoNotOptimize(t = build_spectral_tables(g));
  state.counters["N"] = t.N;
  state.counters["J"] = t.J;
  state.counters["table_MiB"] = double(t.coefficients.size() * sizeof(glm::vec2)) / (1 << 20);
}
BENCHMARK(BM_Precompute)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond)->Iterations(3);

// Tables storing 32 terms per bin, of which the first range(0) are evaluated.
const SpectralTables& tall_tables() {
  static const SpectralTables t = build_spectral_tables(fingers(256, 300.0), {.tolerance = 1e-6});
  return t;
}

std::vector<DiffractionQuery> queries(size_t count) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uni(-0.7, 0.7), lambda(380.0, 780.0);
  auto dir = [&] {
    const double x = uni(rng), y = uni(rng);
    return glm::dvec3(x, y, std::sqrt(1 - x * x - y * y));
  };
  std::vector<DiffractionQuery> qs(count);
  for (auto& q : qs) q = {dir(), dir(), lambda(rng)};
  return qs;
}

void BM_CpuEval(benchmark::State& state) {
  SpectralTables t = tall_tables();
  t.N = static_cast<int>(state.range(0));
  if (t.N > t.stored_terms) return state.SkipWithError("the tables store fewer terms");
  const auto qs = queries(4096);
  for (auto _ : state)
    for (const auto& q : qs) benchmark::DoNotOptimize(evaluate_taylor(t, q));
  state.SetItemsProcessed(state.iterations() * qs.size());
  state.counters["bins"] = (2 * t.r + 1) * (2 * t.r + 1);
}
BENCHMARK(BM_CpuEval)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->Unit(benchmark::kMillisecond);

void BM_GpuEval(benchmark::State& state) {
  static facet::vk::Context context{facet::vk::ContextOptions{}};
  SpectralTables t = tall_tables();
  t.N = static_cast<int>(state.range(0));
  if (t.N > t.stored_terms) return state.SkipWithError("the tables store fewer terms");
  const auto qs = queries(1 << 18);
  facet::gpu::evaluate_diffraction(context, t, qs);  // JIT warm-up
  for (auto _ : state) {
    facet::gpu::BatchTiming timing;
    facet::gpu::evaluate_diffraction(context, t, qs, &timing);
    state.SetIterationTime(timing.gpu_ms * 1e-3);
  }
  state.SetItemsProcessed(state.iterations() * qs.size());
}
BENCHMARK(BM_GpuEval)->Arg(4)->Arg(8)->Arg(16)->Arg(32)->UseManualTime()->Unit(benchmark::kMillisecond);

// range(0): scene (0 plate, 1 snake), range(1): wavelengths, range(2): Taylor terms (0: from the
// scene's tolerance). Manual time = the GPU timestamps of one 512 x 512 frame.
void BM_RenderFrame(benchmark::State& state) {
  const facet::Scene& scene = facet::bench::diffraction_scene(static_cast<int>(state.range(0)));
  facet::gpu::RenderMethod method;
  method.diffraction.wavelengths = static_cast<int>(state.range(1));
  method.diffraction.taylor = static_cast<int>(state.range(2));
  facet::bench::measure_diffraction_frame(state, static_cast<int>(state.range(0)), method);
  const auto prepared = facet::diffraction::prepare_scene_diffraction(scene, method.diffraction);
  for (const auto& p : prepared)
    if (p) {
      state.counters["K"] = double(p->samples.lambda_nm.size());
      state.counters["N"] = p->tables.N;
      state.counters["bins"] = (2 * p->tables.r + 1) * (2 * p->tables.r + 1);
    }
}
BENCHMARK(BM_RenderFrame)
    ->ArgsProduct({{0, 1}, {0}, {0, 4, 8}})
    ->ArgsProduct({{0, 1}, {16, 64}, {0}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

}  // namespace
