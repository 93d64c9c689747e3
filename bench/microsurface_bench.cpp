// Evaluations per second of the shared microsurface kernels on the CPU twins (single thread).
#include <benchmark/benchmark.h>

#include <vector>

#include "kernels/shared.hpp"

namespace {

// A fixed spread of inputs (in front of and far beyond the horizon, both t branches).
template <class Real>
std::vector<Real> thetas() {
  std::vector<Real> v;
  for (int i = 0; i < 64; ++i) v.push_back(Real(0.024) * Real(i));
  return v;
}

template <class Real, class Kernel>
void run(benchmark::State& state, Kernel kernel) {
  const std::vector<Real> theta = thetas<Real>();
  size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(kernel(theta[i++ & 63]));
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_VisibleSlopeF64(benchmark::State& state) {
  run<double>(state, [](double theta) {
    return facet::kernels::f64::visible_slope({0.8, 0.2}, {0.3, 0.5, 0.1}, theta, 0.4);
  });
}
void BM_VisibleSlopeF32(benchmark::State& state) {
  run<float>(state, [](float theta) {
    return facet::kernels::f32::visible_slope({0.8f, 0.2f}, {0.3f, 0.5f, 0.1f}, theta, 0.4f);
  });
}
void BM_SmithLambdaF64(benchmark::State& state) {
  run<double>(state, [](double theta) {
    return facet::kernels::f64::gaussian_smith_lambda({0.8, 0.2}, {0.3, 0.5, 0.1}, theta, 0.4);
  });
}
void BM_SmithLambdaF32(benchmark::State& state) {
  run<float>(state, [](float theta) {
    return facet::kernels::f32::gaussian_smith_lambda({0.8f, 0.2f}, {0.3f, 0.5f, 0.1f}, theta, 0.4f);
  });
}
void BM_ErfcxF64(benchmark::State& state) {
  run<double>(state, [](double x) { return facet::kernels::f64::sf_erfcx(x * 4); });
}
void BM_ErfcxF32(benchmark::State& state) {
  run<float>(state, [](float x) { return facet::kernels::f32::sf_erfcx(x * 4); });
}

BENCHMARK(BM_VisibleSlopeF64);
BENCHMARK(BM_VisibleSlopeF32);
BENCHMARK(BM_SmithLambdaF64);
BENCHMARK(BM_SmithLambdaF32);
BENCHMARK(BM_ErfcxF64);
BENCHMARK(BM_ErfcxF32);

}  // namespace
