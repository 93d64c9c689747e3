// Diffraction fast paths (docs/diffraction_fast_paths.md) on the CPU (double twins, all threads):
// the pre-integrated tables' precompute for a 512^2 height field seen by a camera, and frames of
// direction pairs (a camera's views of a plate under a distant light) coloured by the spectral,
// pre-integrated and order-restricted paths, each with its error against the exact transform on 16
// views across the first order (counter err_vs_exact, relative to the brightest exact view); and the GPU
// (lavapipe) cost of the pre-integrated shading and of the spectral path's evaluations; and whole
// 512 x 512 frames of the two diffraction scenes by each method with their error against the exact transform.
#include <benchmark/benchmark.h>

#include <map>
#include <vector>

#include <tbb/parallel_for.h>

#include "diffraction/cie_tables.hpp"
#include "diffraction/exact_transform.hpp"
#include "diffraction/order_wavelengths.hpp"
#include "diffraction/preintegrated_tables.hpp"
#include "diffraction_frames.hpp"
#include "gpu/diffraction_eval.hpp"
#include "orders_probe.hpp"
#include "preintegrated_probe.hpp"

namespace {

using namespace facet::diffraction;
using Pairs = std::vector<std::pair<glm::dvec3, glm::dvec3>>;

constexpr double kTolerance = 1e-3;       // wavelength sampling and orders
constexpr double kTableTolerance = 1e-2;  // pre-integrated interpolation (F.6)

// Snake-scale-like fingers, 512^2 samples over 16 um, coherence 4 um.
Grating fingers() {
  return grating_from_json({{"type", "fingers"},
                            {"period_nm", 1000},
                            {"amplitude_nm", 80},
                            {"size_um", 16},
                            {"samples", 512},
                            {"finger_length_nm", 2000},
                            {"coherence_um", 4}},
                           "bench");
}

glm::dvec3 direction(double x, double y) { return {x, y, std::sqrt(std::max(0.0, 1.0 - x * x - y * y))}; }

// A width x width frame: a light at 20 degrees, views spanning 0.5 x 0.5 in (x, y) across the first order.
Pairs frame(int width) {
  Pairs pairs;
  const glm::dvec3 light = direction(0.34, 0.0);
  for (int y = 0; y < width; ++y)
    for (int x = 0; x < width; ++x)
      pairs.emplace_back(light, direction(-0.9 + 0.5 * (x + 0.5) / width, -0.25 + 0.5 * (y + 0.5) / width));
  return pairs;
}

struct Setup {
  Grating grating = fingers();
  SpectralTables tables;
  WavelengthSamples samples;
  PreintegratedDomain domain;
  Setup() {
    domain = domain_of_directions(frame(64));
    TableRange range;
    range.lambda_min_nm = kCieLambdaMinNm;
    range.lambda_max_nm = kCieLambdaMaxNm;
    range.w_max = -domain.w_min;
    tables = build_spectral_tables(grating, range);
    samples = diffraction_wavelength_samples(tables, kTolerance);
  }
};

const Setup& setup() {
  static const Setup s;
  return s;
}

void BM_PreintegratedPrecompute(benchmark::State& state) {
  const Setup& s = setup();
  PreintegratedTables t;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        t = build_preintegrated_tables(s.tables, s.samples, s.domain, {.tolerance = kTableTolerance}));
  state.counters["nodes"] = double(t.nu) * t.nv;
  state.counters["terms"] = t.terms;
  state.counters["wavelengths"] = double(s.samples.lambda_nm.size());
  state.counters["MiB"] = double(t.bytes()) / (1 << 20);
}
BENCHMARK(BM_PreintegratedPrecompute)->Unit(benchmark::kMillisecond)->Iterations(1);

using Method = std::function<glm::dvec3(const glm::dvec3&, const glm::dvec3&)>;

// The fingers' rows are shifted by half a period, so their first order leaves at (u, v) = (1, +-1/4)
// lambda / 1000 nm: 16 views on those two streaks (and the dark between) within the frame.
Pairs reference_pairs() {
  Pairs pairs;
  const glm::dvec3 light = direction(0.34, 0.0);
  for (int i = 0; i < 16; ++i) {
    const double u = 0.1 + 0.45 * i / 15.0, v = (i % 2 ? 0.25 : -0.25) * u + (i % 4 == 3 ? 0.01 : 0.0);
    pairs.emplace_back(light, direction(-u - light.x, -v - light.y));
  }
  return pairs;
}

// Largest |method - exact| over the reference views, relative to the brightest exact one. The
// exact transform costs two 512^2 FFTs per wavelength and view, so it is computed once.
double error_vs_exact(const Method& method) {
  const Setup& s = setup();
  static const ExactTransform exact(s.grating, s.tables);
  static const Pairs pairs = reference_pairs();
  static std::vector<glm::dvec3> reference;
  if (reference.empty())
    for (const auto& [wi, wr] : pairs)
      reference.push_back(integrate_linear_srgb(s.samples, [&](double l) { return exact.evaluate({wi, wr, l}).brdf; }));
  double peak = 0.0, worst = 0.0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const glm::dvec3 d = glm::abs(method(pairs[i].first, pairs[i].second) - reference[i]);
    peak = std::max({peak, reference[i].x, reference[i].y, reference[i].z});
    worst = std::max({worst, d.x, d.y, d.z});
  }
  return worst / peak;
}

void run_frame(benchmark::State& state, const Method& method) {
  const Pairs pixels = frame(static_cast<int>(state.range(0)));
  std::vector<glm::dvec3> image(pixels.size());
  for (auto _ : state)
    tbb::parallel_for(size_t(0), pixels.size(),
                      [&](size_t i) { image[i] = method(pixels[i].first, pixels[i].second); });
  state.counters["err_vs_exact"] = error_vs_exact(method);
  state.counters["px_per_s"] = benchmark::Counter(double(pixels.size()), benchmark::Counter::kIsIterationInvariantRate);
}

// range(1) wavelengths uniform over 360..830 nm (0: the tolerance's 169 samples, the reference's own).
void BM_FrameSpectral(benchmark::State& state) {
  const Setup& s = setup();
  const WavelengthSamples samples =
      state.range(1) > 0 ? wavelength_samples(470.0 / double(state.range(1) - 1)) : s.samples;
  run_frame(state, [&](const glm::dvec3& wi, const glm::dvec3& wr) {
    return integrate_linear_srgb(samples, [&](double l) { return evaluate_taylor(s.tables, {wi, wr, l}).brdf; });
  });
  state.counters["wavelengths"] = double(samples.lambda_nm.size());
}

const PreintegratedTables& preintegrated(double tolerance) {
  static std::map<double, PreintegratedTables> cache;
  if (!cache.count(tolerance))
    cache[tolerance] =
        build_preintegrated_tables(setup().tables, setup().samples, setup().domain, {.tolerance = tolerance});
  return cache[tolerance];
}

// range(1): the table tolerance in units of 1e-3.
void BM_FramePreintegrated(benchmark::State& state) {
  const PreintegratedTables& t = preintegrated(1e-3 * double(state.range(1)));
  run_frame(state, [&](const glm::dvec3& wi, const glm::dvec3& wr) { return evaluate_preintegrated(t, wi, wr); });
  state.counters["MiB"] = double(t.bytes()) / (1 << 20);
}

// The pre-integrated shading of a 512 x 512 frame's direction pairs on lavapipe (float, manual
// time = the dispatch's GPU timestamps; ray tracing and the frame's other work not included).
void BM_GpuPreintegrated(benchmark::State& state) {
  const PreintegratedTables& t = preintegrated(1e-3 * double(state.range(1)));
  const Pairs pixels = frame(static_cast<int>(state.range(0)));
  static facet::vk::Context context{facet::vk::ContextOptions{}};
  for (auto _ : state) state.SetIterationTime(1e-3 * facet::test::run_preintegrated_probe(context, t, pixels).gpu_ms);
  state.counters["px_per_s"] = benchmark::Counter(double(pixels.size()), benchmark::Counter::kIsIterationInvariantRate);
}

// The order-restricted shading of a frame on lavapipe (float, manual time = GPU timestamps).
void BM_GpuOrders(benchmark::State& state) {
  const Setup& s = setup();
  static const OrderWavelengths plan =
      plan_order_wavelengths(s.grating, s.tables, kTolerance, Illuminant::D65, s.samples);
  const Pairs pixels = frame(static_cast<int>(state.range(0)));
  static facet::vk::Context context{facet::vk::ContextOptions{}};
  for (auto _ : state)
    state.SetIterationTime(1e-3 * facet::test::run_orders_probe(context, s.tables, plan, pixels).gpu_ms);
  state.counters["px_per_s"] = benchmark::Counter(double(pixels.size()), benchmark::Counter::kIsIterationInvariantRate);
}

// The spectral path's cost on lavapipe per (pixel, wavelength) evaluation: 64 x 64 pixels x
// range(1) wavelengths as one batch of eval_diffraction (a 512 x 512 frame is 64 times as many).
void BM_GpuSpectralEvaluations(benchmark::State& state) {
  const Setup& s = setup();
  const WavelengthSamples samples = wavelength_samples(470.0 / double(state.range(1) - 1));
  std::vector<DiffractionQuery> queries;
  for (const auto& [wi, wr] : frame(static_cast<int>(state.range(0))))
    for (double l : samples.lambda_nm) queries.push_back({wi, wr, l});
  static facet::vk::Context context{facet::vk::ContextOptions{}};
  for (auto _ : state) {
    facet::gpu::BatchTiming timing;
    benchmark::DoNotOptimize(facet::gpu::evaluate_diffraction(context, s.tables, queries, &timing));
    state.SetIterationTime(1e-3 * timing.gpu_ms);
  }
  state.counters["evals_per_s"] =
      benchmark::Counter(double(queries.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_FrameOrders(benchmark::State& state) {
  const Setup& s = setup();
  static const OrderWavelengths plan =
      plan_order_wavelengths(s.grating, s.tables, kTolerance, Illuminant::D65, s.samples);
  run_frame(state, [&](const glm::dvec3& wi, const glm::dvec3& wr) { return evaluate_orders(s.tables, plan, wi, wr); });
  state.counters["restricted"] = plan.restricted;
}

// Whole frames of the diffraction scenes (issue 11), timed and measured as diffraction_bench's
// BM_RenderFrame (diffraction_frames.hpp). range(0): scene (0 plate, 1 snake), range(1): method
// (0 spectral, 1 preintegrated, 2 orders), range(2): wavelengths (0: the tolerance's).
void BM_RenderScene(benchmark::State& state) {
  facet::gpu::RenderMethod method;
  method.diffraction.method = static_cast<DiffractionMethod>(state.range(1));
  method.diffraction.wavelengths = static_cast<int>(state.range(2));
  facet::bench::measure_diffraction_frame(state, static_cast<int>(state.range(0)), method);
}
BENCHMARK(BM_RenderScene)
    ->ArgsProduct({{0, 1}, {0}, {0, 32, 64, 72, 80, 96}})
    ->ArgsProduct({{0, 1}, {1, 2}, {0}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

BENCHMARK(BM_FrameSpectral)
    ->Args({64, 16})
    ->Args({64, 32})
    ->Args({64, 64})
    ->Args({64, 0})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(BM_FramePreintegrated)->Args({512, 10})->Args({512, 3})->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_FrameOrders)->Arg(64)->Arg(512)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_GpuPreintegrated)
    ->Args({512, 10})
    ->Args({512, 3})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(3);
BENCHMARK(BM_GpuOrders)->Arg(512)->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_GpuSpectralEvaluations)->Args({64, 32})->UseManualTime()->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
