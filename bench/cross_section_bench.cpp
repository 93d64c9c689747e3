// Evaluations per second of the cross-sections on the CPU: the exact spherical-Gaussian quadrature,
// the fast shared kernel (float as on the GPU, and its double twin), and the closed forms. Each
// benchmark cycles through 4096 (alpha, u) pairs spread log-uniformly over alpha in [1e-3, 1e3] and
// uniformly over u in [-1, 1]; the counter max_err is the worst of |sigma - exact| / max(1, exact) on
// that set (Beckmann and GGX reach sigma = alpha/2 = 500; 0 for the exact evaluations themselves,
// whose accuracy tests/kernels establishes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "kernels/cross_section_exact.hpp"
#include "kernels/shared.hpp"

namespace {

using namespace facet::kernels;

struct Inputs {
  std::vector<double> param;
  std::vector<double> u;
};

Inputs make_inputs(int ndf) {
  Inputs in;
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  for (int i = 0; i < 4096; ++i) {
    double x = uniform(rng);
    in.param.push_back(ndf == NDF_KK ? 1e-6 + (1 - 2e-6) * x : std::pow(10.0, -3.0 + 6.0 * x));
    in.u.push_back(-1.0 + 2.0 * uniform(rng));
  }
  return in;
}

template <typename F>
void run(benchmark::State& state, int ndf, F&& eval) {
  Inputs in = make_inputs(ndf);
  double worst = 0.0;
  for (std::size_t i = 0; i < in.u.size(); ++i) {
    double exact = cross_section(ndf, in.param[i], in.u[i], true);
    worst = std::max(worst, std::abs(eval(in.param[i], in.u[i]) - exact) / std::max(1.0, exact));
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(eval(in.param[i], in.u[i]));
    i = (i + 1) & 4095;
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["max_err"] = worst;
}

void BM_SgExact(benchmark::State& s) {
  run(s, NDF_SG, [](double a, double u) { return sg_cross_section_exact(a, u); });
}
void BM_SgFastFloat(benchmark::State& s) {
  run(s, NDF_SG, [](double a, double u) { return double(f32::ndf_sg_sigma_u(float(u), float(a))); });
}
void BM_SgFastDouble(benchmark::State& s) {
  run(s, NDF_SG, [](double a, double u) { return f64::ndf_sg_sigma_u(u, a); });
}
void BM_ClosedFormFloat(benchmark::State& s) {
  int ndf = int(s.range(0));
  run(s, ndf, [ndf](double p, double u) { return double(f32::ndf_sigma_u(ndf, float(u), float(p))); });
}

BENCHMARK(BM_SgExact);
BENCHMARK(BM_SgFastFloat);
BENCHMARK(BM_SgFastDouble);
BENCHMARK(BM_ClosedFormFloat)->Arg(NDF_BECKMANN)->Arg(NDF_GGX)->Arg(NDF_KK);

}  // namespace
